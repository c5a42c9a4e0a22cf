// Glass in the real-time voxel solvers' pictures (sky visibility, radiance cascades;
// docs/algorithms/voxel-radiance-cascades.md §4.2): the sun's shadow rays pass through glass
// with its Fresnel transmission and Beer-Lambert absorption along the straight line; a mirror
// that shows a glass block shows what lies behind it; a mirror and a glass pane show the sun's
// disk; a mirror seen through glass shows what it reflects. Each picture of before (glass opaque
// to the sun, the glass or mirror met by a reflected ray an opaque face, no disk) is outside the
// bounds.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/shaders/shared/optics.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/sky_visibility.h"
#include "luxel/voxel/surface_cast.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/solver_sun.h"
#include "voxel/sun_disk.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr double kPi = 3.14159265358979323846;
constexpr Voxel kGlass{255, 255, 255, 1};  // texture slot 0
constexpr Voxel kSlot1{255, 255, 255, 2};

struct Pictures {
    Image ao, rc;
};

// Sky visibility's picture and the cascades' (after their lighting passes when `passes`).
Pictures renderBoth(const VoxelWorld& world, const ShadeOptions& o, const Camera& camera,
                    bool passes = true) {
    auto sky = renderSkyVisibility(world, camera, o, SkyVisibilityOptions{});
    EXPECT_TRUE(sky.ok());
    auto cascades = RadianceCascades::create(world, nullptr, o, CascadeOptions{});
    EXPECT_TRUE(cascades.ok());
    if (passes) cascades->solve();
    auto rc = cascades->render(camera);
    EXPECT_TRUE(rc.ok());
    return {std::move(sky->radiance), std::move(*rc)};
}

// A white floor (y = 0, Lambertian of albedo 0.5) under a clear glass slab two voxels thick
// (y = 4..5 over x, z in 4..20) that absorbs 0.2 per voxel and reflects nothing diffusely (albedo
// 0, so no light bounces off it in the cascades); a delta sun, a black sky.
struct SlabScene {
    VoxelWorld world = makeWorld({24, 8, 24});
    ShadeOptions o;
    Vec3d sun = normalize(Vec3d{0.25, 1.0, 0.15});
    SlabScene() {
        for (int z = 0; z < 24; ++z)
            for (int x = 0; x < 24; ++x) {
                world.set(x, 0, z, kWhite);
                if (x >= 4 && x < 20 && z >= 4 && z < 20) {
                    for (int y = 4; y < 6; ++y) world.set(x, y, z, kGlass);
                }
            }
        world.refreshEmptySpace();
        o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
        o.sunIrradiance = Rgb(2.0f);
        o.sunDirection = Vec3(float(sun.x), float(sun.y), float(sun.z));
        Material g = glass(Rgb(0.2f));
        g.albedo = Rgb(0.0f);
        EXPECT_TRUE(o.materials.setSlot(0, g).ok());
    }
    // The floor's radiance where the sun reaches it through the slab: albedo E cos / pi x
    // (1 - F)^2 x exp(-sigma d), F at the sun's angle to the slab, d = 2 / cos along the line.
    double underTheSlab() const {
        const double cosSun = sun.y;
        const double f = gpu::shared::fresnelDielectricExact(float(cosSun), 1.0f, 1.5f);
        return 0.5 * 2.0 * cosSun / kPi * (1 - f) * (1 - f) * std::exp(-0.2 * 2.0 / cosSun);
    }
    // Whether the sun ray from a floor point crosses the slab's top and bottom well inside it.
    bool sunThroughTheSlab(Vec3d p) const {
        for (const double y : {4.0, 6.0}) {
            const Vec3d q = p + sun * ((y - p.y) / sun.y);
            if (q.x < 5 || q.x > 19 || q.z < 5 || q.z > 19) return false;
        }
        return true;
    }
};

TEST(SolverGlass, SunThroughAGlassSlabIsFresnelAndBeerLambert) {
    const SlabScene scene;
    // Under the slab's edge, looking in along +z just above the floor.
    const Camera camera = *Camera::lookAt({12.0, 2.5, 2.0}, {12.0, 1.0, 12.0}, 30.0, 16, 12);
    // No lighting passes for the cascades: their picture is the direct light alone (the passes
    // bring 0.6% more under the slab, their own error, the sky being black).
    const Pictures p = renderBoth(scene.world, scene.o, camera, false);
    const double want = scene.underTheSlab();
    int checked = 0;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x) {
            const SurfaceHit s = castToSurface(scene.world, nullptr, camera.primaryRay(x, y));
            if (!s.hit.hit || s.hit.normal != Int3{0, 1, 0} ||
                !scene.sunThroughTheSlab(s.hit.point))
                continue;
            ++checked;
            // Glass opaque to the sun, as before, gave 0 here.
            EXPECT_NEAR(p.ao.at(x, y, 0), want, 1e-4 * want) << "sky visibility " << x << "," << y;
            EXPECT_NEAR(p.rc.at(x, y, 0), want, 1e-4 * want) << "cascades " << x << "," << y;
        }
    EXPECT_GT(checked, 20);
}

TEST(SolverGlass, SunRayTransmittanceThroughMediaAndOpaqueBlocks) {
    const SlabScene scene;
    const double want = scene.underTheSlab() / (0.5 * 2.0 * scene.sun.y / kPi);
    const Ray up{{12.0, 1.0, 12.0}, scene.sun};
    EXPECT_NEAR(sunRayTransmittance(scene.world, nullptr, up, scene.o).g, want, 1e-5);
    // Outside the slab the sun is open; an opaque block over the slab still stops it.
    EXPECT_EQ(sunRayTransmittance(scene.world, nullptr, {{1.0, 1.0, 1.0}, scene.sun}, scene.o).g,
              1.0f);
    VoxelWorld blocked = scene.world;
    for (int z = 0; z < 24; ++z)
        for (int x = 0; x < 24; ++x) blocked.set(x, 7, z, kWhite);
    blocked.refreshEmptySpace();
    EXPECT_EQ(sunRayTransmittance(blocked, nullptr, up, scene.o).g, 0.0f);
    // Without refraction glass is opaque, as in the ray caster.
    ShadeOptions opaque = scene.o;
    opaque.refraction = false;
    EXPECT_EQ(sunRayTransmittance(scene.world, nullptr, up, opaque).g, 0.0f);
}

// The cascades' stored sun of each face (what reflections and the lighting passes read): a mirror
// wall at z = 23 seen by a camera under the slab shows the floor under the slab lit through it.
// No lighting pass is run, so the picture has no indirect light (the mirror's faces are
// Lambertian in the passes and would light the floor) and the stored sun is read alone.
TEST(SolverGlass, CascadesFaceSunPassesThroughGlass) {
    SlabScene scene;
    for (int y = 1; y < 8; ++y)
        for (int x = 0; x < 24; ++x) scene.world.set(x, y, 23, kSlot1);
    scene.world.refreshEmptySpace();
    ASSERT_TRUE(scene.o.materials.setSlot(1, metal(0.0f, Rgb(1.0f))).ok());
    // Looking at the mirror from under the slab: the reflection falls on the floor under it.
    const Camera camera = *Camera::lookAt({12.0, 3.0, 14.0}, {12.0, 2.0, 23.0}, 20.0, 8, 6);
    auto cascades = RadianceCascades::create(scene.world, nullptr, scene.o, CascadeOptions{});
    ASSERT_TRUE(cascades.ok());
    auto rc = cascades->render(camera);
    ASSERT_TRUE(rc.ok());
    const double want = scene.underTheSlab();
    int checked = 0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const Ray ray = camera.primaryRay(x, y);
            const SurfaceHit m = castToSurface(scene.world, nullptr, ray);
            if (!m.hit.hit || m.hit.voxel.z != 23) continue;
            const Vec3d d = normalize(ray.direction);
            const SurfaceHit s =
                castToSurface(scene.world, nullptr, {m.hit.point, {d.x, d.y, -d.z}});
            if (!s.hit.hit || s.hit.normal != Int3{0, 1, 0}) continue;
            // The face's four quarter points must all see the sun through the slab.
            const Vec3d c{s.hit.voxel.x + 0.5, 1.0, s.hit.voxel.z + 0.5};
            if (!scene.sunThroughTheSlab(c + Vec3d{-0.5, 0, -0.5}) ||
                !scene.sunThroughTheSlab(c + Vec3d{0.5, 0, 0.5})) {
                continue;
            }
            ++checked;
            EXPECT_NEAR(rc->at(x, y, 0), want, 2e-3 * want) << x << "," << y;
        }
    EXPECT_GT(checked, 8);
}

// A mirror wall (x = 0, polished metal), a clear glass slab over x in [glassFrom, glassTo) that
// absorbs 0.2 per voxel and reflects nothing diffusely, and a wall glowing 2 (x = 15) under a
// black sky: what the mirror and the glass show of the wall has a closed form.
struct MirrorGlassLamp {
    VoxelWorld world = makeWorld({16, 8, 8});
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    MirrorGlassLamp(int glassFrom, int glassTo) {
        for (int z = 0; z < 8; ++z)
            for (int y = 0; y < 8; ++y) {
                world.set(0, y, z, kSlot1);
                for (int x = glassFrom; x < glassTo; ++x) world.set(x, y, z, kGlass);
                world.set(15, y, z, Voxel{255, 255, 255, 3});
            }
        world.refreshEmptySpace();
        Material g = glass(Rgb(0.2f));
        g.albedo = Rgb(0.0f);
        Material lamp = lampMaterial(Rgb(2.0f));
        lamp.albedo = Rgb(0.0f);
        EXPECT_TRUE(o.materials.setSlot(0, g).ok());
        EXPECT_TRUE(o.materials.setSlot(1, metal(0.0f, Rgb(1.0f))).ok());
        EXPECT_TRUE(o.materials.setSlot(2, lamp).ok());
    }
};

// A mirror wall (x = 0) seen head-on; behind the camera a clear glass slab three voxels thick
// (x = 10..12) and a glowing wall (x = 15), the sky black: the mirror shows the wall through the
// glass with the Fresnel series and Beer-Lambert, (1 - F)^2 t / (1 - F^2 t^2), less the light
// the glass and the mirror reflect back and forth (about F (1 - F)^2 t, 3%). The glass shaded as
// an opaque face of albedo 0 showed black.
TEST(SolverGlass, MirrorShowsWhatLiesBehindGlass) {
    const MirrorGlassLamp scene(10, 13);
    const VoxelWorld& world = scene.world;
    const ShadeOptions& o = scene.o;
    const double f = 0.04, t = std::exp(-0.2 * 3.0);
    const double want = 2.0 * (1 - f) * (1 - f) * t / (1 - f * f * t * t);

    const Camera camera = *Camera::create({6.0, 4.3, 4.2}, -90.0, 0.0, 4.0, 4, 4);
    const Pictures p = renderBoth(world, o, camera);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            EXPECT_NEAR(p.ao.at(x, y, 0), want, 0.005 * want) << "sky visibility " << x << "," << y;
            EXPECT_NEAR(p.rc.at(x, y, 0), want, 0.005 * want) << "cascades " << x << "," << y;
        }
}

// Polished metal met by a followed ray is followed too: looking along -x through a clear glass
// slab (x = 8..9, absorbing 0.2 per voxel) at a mirror wall (x = 0) that reflects a glowing wall
// behind the camera (x = 15), the sky black. The pixel is the slab's reflection of the glowing
// wall, 2 R with R = F + (1 - F)^2 F t^2 / (1 - F^2 t^2), plus the wall seen through the slab
// twice by way of the mirror, 2 S^2 with S = (1 - F)^2 t / (1 - F^2 t^2); the mirror shaded as
// an opaque face gave 2 R alone.
TEST(SolverGlass, MirrorSeenThroughGlassShowsWhatItReflects) {
    const MirrorGlassLamp scene(8, 10);
    const VoxelWorld& world = scene.world;
    const ShadeOptions& o = scene.o;
    const double f = 0.04, t = std::exp(-0.2 * 2.0);
    const double slab = (1 - f) * (1 - f) * t / (1 - f * f * t * t);
    const double reflected = f + (1 - f) * (1 - f) * f * t * t / (1 - f * f * t * t);
    const double want = 2.0 * reflected + 2.0 * slab * slab;

    const Camera camera = *Camera::create({14.0, 4.3, 4.2}, -90.0, 0.0, 4.0, 4, 4);
    const Pictures p = renderBoth(world, o, camera);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            EXPECT_NEAR(p.ao.at(x, y, 0), want, 0.01 * want) << "sky visibility " << x << "," << y;
            EXPECT_NEAR(p.rc.at(x, y, 0), want, 0.01 * want) << "cascades " << x << "," << y;
        }
}

// A mirror floor under a black sky and a sun of radius 0.1 rad in the mirror direction of the
// view's centre: the centre pixel shows the disk's radiance E / (pi sin^2 r), pixels outside the
// disk's image are black. Looking up through a glass pane at the same sun shows the disk dimmed
// by the pane's two interfaces.
TEST(SolverGlass, MirrorAndGlassShowTheSunsDisk) {
    VoxelWorld world = makeWorld({32, 8, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) world.set(x, 0, z, kSlot1);
    world.refreshEmptySpace();
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    ASSERT_TRUE(o.materials.setSlot(1, metal(0.0f, Rgb(1.0f))).ok());
    ASSERT_TRUE(o.materials.setSlot(0, glass()).ok());
    const Camera camera = *Camera::create({16.0, 4.0, 4.0}, 0.0, -30.0, 40.0, 9, 9);
    const Vec3d d = normalize(camera.primaryRay(4, 4).direction);
    o.sunDirection = Vec3(float(d.x), float(-d.y), float(d.z));
    o.sunIrradiance = Rgb(3.0f);
    o.sunAngularRadius = 0.1;
    const double disk = 3.0 / (kPi * std::sin(0.1) * std::sin(0.1));
    EXPECT_NEAR(sunDiskAlong({d.x, -d.y, d.z}, o).r, disk, 1e-4 * disk);
    const Pictures p = renderBoth(world, o, camera);
    // A metal of colour 1 reflects everything (Schlick of 1).
    EXPECT_NEAR(p.ao.at(4, 4, 0), disk, 1e-3 * disk);
    EXPECT_NEAR(p.rc.at(4, 4, 0), disk, 1e-3 * disk);
    EXPECT_EQ(p.ao.at(0, 0, 0), 0.0f);
    EXPECT_EQ(p.rc.at(0, 0, 0), 0.0f);

    // Up through a pane (y = 6, one voxel thick, clear) at the sun square above it.
    VoxelWorld pane = makeWorld({32, 8, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) pane.set(x, 6, z, kGlass);
    pane.refreshEmptySpace();
    o.sunDirection = Vec3(0.0f, 1.0f, 0.0f);
    const Camera up = *Camera::create({16.0, 2.0, 16.0}, 0.0, 90.0, 20.0, 5, 5);
    const Pictures q = renderBoth(pane, o, up);
    const double f = 0.04;
    // The transmitted part of each internal reflection leaves upwards too: (1 - F)^2 / (1 - F^2).
    const double through = disk * (1 - f) * (1 - f) / (1 - f * f);
    EXPECT_NEAR(q.ao.at(2, 2, 0), through, 2e-3 * through);
    EXPECT_NEAR(q.rc.at(2, 2, 0), through, 2e-3 * through);
}

// The cascades' camera surface shares the disk's walk through glass (solverSunLobes' shareMedia;
// docs/algorithms/voxel-radiance-cascades.md §4.2, "Sun rays through glass"): where the spiral's
// first ray passes the slab, every ray takes its transmittance; where it reaches the sky, each
// ray is walked as before; without media nothing is shared.
TEST(SolverGlass, SunRaysShareTheFirstRaysWalkThroughGlass) {
    SlabScene scene;
    scene.o.sunAngularRadius = 0.05;  // about 3 degrees, so the rays part visibly
    const SunDisk sun = SunDisk::make(scene.o.sunDirection, scene.o.sunAngularRadius);
    const int rays = 4;
    const auto floorAt = [](double x, double z) {
        Hit h;
        h.hit = true;
        h.voxel = {int(x), 0, int(z)};
        h.normal = {0, 1, 0};
        h.point = {x, 1.0, z};
        return h;
    };
    const auto lobes = [&](const Hit& h, bool share, const ShadeOptions& o) {
        return solverSunLobes(scene.world, nullptr, h, Rgb(0.5f), nullptr, o, rays, nullptr, share);
    };
    const auto transmittance = [&](const Hit& h, int i, const ShadeOptions& o) {
        return sunRayTransmittance(scene.world, nullptr, {h.point, sun.spiral(i, rays)}, o);
    };
    // Under the slab's middle: the first ray's transmittance for all, within 2e-3 of each ray's own
    // (the rays cross the slab at angles up to 6 degrees apart, their paths inside differing a
    // little).
    const Hit middle = floorAt(12.3, 11.7);
    const Rgb first = transmittance(middle, 0, scene.o);
    ASSERT_GT(first.g, 0.1f);
    ASSERT_LT(first.g, 0.9f);
    double cosines = 0.0;
    for (int i = 0; i < rays; ++i) cosines += sun.spiral(i, rays).y;
    const Rgb perRay = sun.radianceOverPdf(scene.o.sunIrradiance) * float(1.0 / rays);
    const Rgb shared = lobes(middle, true, scene.o);
    EXPECT_NEAR(shared.g, 0.5 * perRay.g * first.g * cosines / kPi, 1e-6 * shared.g);
    EXPECT_NEAR(shared.g, lobes(middle, false, scene.o).g, 2e-3 * shared.g);
    // Along the slab's edge: where the first ray is open and another passes the slab, the rays
    // are each walked; where the first passes it and another is open, the open one is dimmed.
    int openFirst = 0, sharedEdge = 0;
    for (double x = 18.0; x < 21.0; x += 0.002) {
        const Hit h = floorAt(x, 12.5);
        const float t0 = transmittance(h, 0, scene.o).g;
        bool anyOpen = false, anyMedium = false;
        for (int i = 1; i < rays; ++i) {
            const float t = transmittance(h, i, scene.o).g;
            anyOpen = anyOpen || t == 1.0f;
            anyMedium = anyMedium || (t > 0.0f && t < 1.0f);
        }
        if (t0 == 1.0f && anyMedium) {
            ++openFirst;
            EXPECT_EQ(lobes(h, true, scene.o).g, lobes(h, false, scene.o).g) << x;
        }
        if (t0 < 1.0f && anyOpen) {
            ++sharedEdge;
            EXPECT_LT(lobes(h, true, scene.o).g, lobes(h, false, scene.o).g) << x;
        }
    }
    EXPECT_GT(openFirst, 0);
    EXPECT_GT(sharedEdge, 0);
    // Glass opaque (refraction off): 0 or 1 per ray, nothing shared, the same to the bit.
    ShadeOptions opaque = scene.o;
    opaque.refraction = false;
    for (double x = 2.0; x < 22.0; x += 0.01) {
        const Hit h = floorAt(x, 12.5);
        EXPECT_EQ(lobes(h, true, opaque).g, lobes(h, false, opaque).g) << x;
    }
}

}  // namespace
