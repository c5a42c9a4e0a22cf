// New light that changes what passes glass (docs/algorithms/voxel-radiance-cascades.md §4.2):
// turning refraction off or on, making the glass opaque, changing its absorption. After
// RadianceCascades::setLight the faces (those under glass are probes only while the glass lets
// light through), the segments' runs through glass, the irradiance and the picture are those of
// a fresh create() with the new light.
#include <gtest/gtest.h>

#include <string>

#include "luxel/voxel/radiance_cascades.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr Voxel kLamp{255, 255, 255, 2};  // texture slot 1

// floorWithGlass with an opaque voxel inside the glass block and a lamp beside the slab.
VoxelWorld floorWithGlassAndLamp() {
    VoxelWorld world = floorWithGlass();
    world.set(13, 2, 14, kWhite);
    world.set(12, 1, 6, kLamp);
    world.refreshEmptySpace();
    return world;
}

ShadeOptions glassLight() {
    ShadeOptions o = plainLight(0.7f, Rgb(0.0f), Rgb(0.8f, 0.9f, 1.0f));
    o.sunIrradiance = Rgb(3.0f);
    o.sunDirection = {0.4f, 1.0f, 0.3f};
    EXPECT_TRUE(o.materials.setSlot(0, glass(Rgb(0.1f, 0.05f, 0.02f))).ok());
    EXPECT_TRUE(o.materials.setSlot(1, lampMaterial(Rgb(6.0f, 5.0f, 3.0f))).ok());
    return o;
}

RadianceCascades build(const VoxelWorld& world, const ShadeOptions& o) {
    auto made = RadianceCascades::create(world, nullptr, o);
    EXPECT_TRUE(made.ok()) << made.error().message();
    return std::move(*made);
}

Image picture(const RadianceCascades& cascades) {
    auto cam = Camera::create({10.0, 9.0, 24.0}, 180.0, -35.0, 60.0, 32, 18);
    EXPECT_TRUE(cam.ok());
    auto image = cascades.render(*cam);
    EXPECT_TRUE(image.ok()) << image.error().message();
    return std::move(*image);
}

constexpr Int3 kNormals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// Every face of the world, at a point off its centre: the two give the same irradiance to
// `tolerance` of the largest (0: exactly), and the same faces are probes (non-zero).
void expectSameIrradiance(const VoxelWorld& world, const RadianceCascades& a,
                          const RadianceCascades& b, float tolerance, const std::string& what) {
    const Int3 s = world.size();
    float largest = 0.0f;
    for (int pass = 0; pass < 2; ++pass)
        for (int z = 0; z < s.z; ++z)
            for (int y = 0; y < s.y; ++y)
                for (int x = 0; x < s.x; ++x)
                    for (int n = 0; n < 6; ++n) {
                        const Int3 d = kNormals[n];
                        const Vec3d p{x + 0.5 + 0.5 * d.x + 0.2 * (d.x == 0),
                                      y + 0.5 + 0.5 * d.y + 0.1 * (d.y == 0),
                                      z + 0.5 + 0.5 * d.z - 0.3 * (d.z == 0)};
                        const Rgb ea = a.indirectIrradiance({x, y, z}, d, p);
                        const Rgb eb = b.indirectIrradiance({x, y, z}, d, p);
                        for (int c = 0; c < 3; ++c) {
                            if (pass == 0) {
                                largest = std::max(largest, eb[c]);
                                continue;
                            }
                            ASSERT_NEAR(ea[c], eb[c], tolerance * largest)
                                << what << ": " << x << "," << y << "," << z << " normal " << n;
                            ASSERT_EQ(ea[c] > 0.0f, eb[c] > 0.0f)
                                << what << ": " << x << "," << y << "," << z << " " << n;
                        }
                    }
    EXPECT_GT(largest, 0.1f) << what;
}

void expectSameStats(const CascadeStats& a, const CascadeStats& b, const std::string& what) {
    EXPECT_EQ(a.faces, b.faces) << what;
    EXPECT_EQ(a.levels, b.levels) << what;
    EXPECT_EQ(a.spacing, b.spacing) << what;
    EXPECT_EQ(a.probes, b.probes) << what;
    EXPECT_EQ(a.segments, b.segments) << what;
    EXPECT_EQ(a.passages, b.passages) << what;
    EXPECT_EQ(a.bytes, b.bytes) << what;
}

// Made with `before`, then given `after` before any pass, against made with `after`: the same
// faces and runs through glass, and after three passes the same irradiance and picture.
void expectFreshAfterChange(const ShadeOptions& before, const ShadeOptions& after,
                            const std::string& what) {
    const VoxelWorld world = floorWithGlassAndLamp();
    RadianceCascades changed = build(world, before);
    ASSERT_TRUE(changed.setLight(after).ok()) << what;
    RadianceCascades fresh = build(world, after);
    expectSameStats(changed.stats(), fresh.stats(), what);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(changed.iterate(), fresh.iterate()) << what;
    expectSameIrradiance(world, changed, fresh, 0.0f, what);
    const Image a = picture(changed), b = picture(fresh);
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(a.at(x, y, c), b.at(x, y, c)) << what << ": " << x << "," << y;
            }
}

TEST(CascadesGlassLight, TurningRefractionOffOrOnBuildsWhatAFreshCreateBuilds) {
    const ShadeOptions on = glassLight();
    ShadeOptions off = on;
    off.refraction = false;
    // The faces under glass are probes only while refraction is on.
    const VoxelWorld world = floorWithGlassAndLamp();
    EXPECT_GT(build(world, on).stats().faces, build(world, off).stats().faces);
    EXPECT_EQ(build(world, off).stats().passages, 0);
    expectFreshAfterChange(on, off, "refraction turned off");
    expectFreshAfterChange(off, on, "refraction turned on");
}

TEST(CascadesGlassLight, GlassMadeOpaqueOrMoreAbsorbingBuildsWhatAFreshCreateBuilds) {
    const ShadeOptions clear = glassLight();
    ShadeOptions opaque = clear;
    Material frosted = glass();
    frosted.transmission = 0.0f;  // glass that counts as opaque: no faces under it
    ASSERT_TRUE(opaque.materials.setSlot(0, frosted).ok());
    ShadeOptions dark = clear;
    ASSERT_TRUE(dark.materials.setSlot(0, glass(Rgb(0.8f))).ok());
    expectFreshAfterChange(clear, opaque, "glass made opaque");
    expectFreshAfterChange(opaque, clear, "glass made clear");
    expectFreshAfterChange(clear, dark, "glass made darker");
}

// Passes run before the change: the irradiance gathered so far stays with its face, and the
// passes after converge to what a fresh build converges to (40 passes each: what is left of the
// start shrinks by the albedo, 0.7, at each).
TEST(CascadesGlassLight, IrradianceGatheredBeforeTheChangeConvergesToTheFreshBuilds) {
    const VoxelWorld world = floorWithGlassAndLamp();
    const ShadeOptions on = glassLight();
    ShadeOptions off = on;
    off.refraction = false;
    RadianceCascades changed = build(world, on);
    changed.solve();
    ASSERT_TRUE(changed.setLight(off).ok());
    RadianceCascades fresh = build(world, off);
    for (int i = 0; i < 40; ++i) changed.iterate(), fresh.iterate();
    expectSameIrradiance(world, changed, fresh, 1e-4f, "converged after the change");
}

}  // namespace
