// The ray caster's light from emissive voxels (emitter_light.h) against ground truth: the
// irradiance a one-voxel lamp gives a floor against a brute-force quadrature of the form factor
// (an independent check of Lambert's contour integral and of which faces count), a one-voxel
// wall's full shadow, glass that passes part of the light, the switch that restores the old
// picture, finite values where the receiving point touches the lamp, and the scene fields.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::voxel {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr Voxel kWhite{255, 255, 255, 255};
constexpr Voxel kLamp{255, 255, 255, 1};  // texture slot 0: the lamp's material
constexpr Voxel kGlass{255, 255, 255, 2};

// Physical lighting in the dark: no sun, a black sky, no highlights; a white Lambertian floor
// (ior 1: no Fresnel) and a lamp of radiance `l` in slot 0, clear glass in slot 1.
ShadeOptions darkRoom(Rgb l) {
    ShadeOptions o;
    o.lighting = ShadeOptions::Lighting::Physical;
    o.textures = false;
    o.specular = ShadeOptions::Specular::None;
    o.sunIrradiance = {};
    o.skyTop = o.skyHorizon = {};
    o.skyAmbient = 0.0f;
    Material plain = defaultMaterial();
    plain.ior = 1.0f;
    plain.albedo = Rgb(1.0f);
    EXPECT_TRUE(o.materials.setPlain(plain).ok());
    Material lamp = plain;
    lamp.emission = l;
    EXPECT_TRUE(o.materials.setSlot(0, lamp).ok());
    Material glass = defaultMaterial();
    glass.ior = 1.5f;
    glass.roughness = 0.0f;
    glass.transmission = 1.0f;
    glass.absorption = {0.2f, 0.2f, 0.2f};
    EXPECT_TRUE(o.materials.setSlot(1, glass).ok());
    return o;
}

// A 24^3 world with a white floor at y = 0 (its top face at y = 1).
VoxelWorld floorWorld() {
    VoxelWorld world = VoxelWorld::create({24, 24, 24}, 8).value();
    for (int z = 0; z < 24; ++z) {
        for (int x = 0; x < 24; ++x) world.set(x, 0, z, kWhite);
    }
    return world;
}

// The irradiance at `p` on an upward face from the box of emissive voxels [lo, hi) of radiance 1:
// the form factor of each of its outer faces that face p, by the midpoint rule on an n x n grid
// per unit of its side (no occluders).
double quadratureIrradiance(Vec3d p, Int3 lo, Int3 hi, int n) {
    double sum = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const double plane = side == 1 ? hi[axis] : lo[axis];
            const double outward = side == 1 ? 1.0 : -1.0;
            if (!((p[axis] - plane) * outward > 0.0)) continue;  // p behind this face
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const int na = n * (hi[a] - lo[a]), nb = n * (hi[b] - lo[b]);
            for (int i = 0; i < na; ++i) {
                for (int j = 0; j < nb; ++j) {
                    Vec3d q;
                    q[axis] = plane;
                    q[a] = lo[a] + (i + 0.5) / n;
                    q[b] = lo[b] + (j + 0.5) / n;
                    const Vec3d d = q - p;
                    const double r2 = dot(d, d);
                    const double cosReceiver = d.y / std::sqrt(r2);
                    const double cosEmitter = -d[axis] * outward / std::sqrt(r2);
                    if (cosReceiver <= 0.0 || cosEmitter <= 0.0) continue;
                    sum += cosReceiver * cosEmitter / r2 / (double(n) * n);
                }
            }
        }
    }
    return sum;  // the projected solid angle: E = L * sum
}

// The same for the unit cube `lamp`.
double quadratureIrradiance(Vec3d p, Int3 lamp, int n = 400) {
    return quadratureIrradiance(p, lamp, {lamp.x + 1, lamp.y + 1, lamp.z + 1}, n);
}

// The irradiance the ray caster takes at a point of the floor: its light with albedo pi.
Rgb floorIrradiance(const EmitterLights& lights, const VoxelWorld& world, const ShadeOptions& o,
                    Vec3d p) {
    EmitterLights::Surface s;
    s.point = p;
    s.faceNormal = {0, 1, 0};
    s.shadingNormal = {0, 1, 0};
    s.view = {0, 1, 0};
    s.diffuseAlbedo = Rgb(float(kPi));
    int budget = kEmitterPathRays;
    return lights.light(world, nullptr, s, o, o.emitterRays, budget);
}

TEST(EmitterLight, FloorIrradianceMatchesTheFormFactorQuadrature) {
    VoxelWorld world = floorWorld();
    const Int3 lamp{12, 4, 12};
    world.set(lamp.x, lamp.y, lamp.z, kLamp);
    const Rgb l{1.5f, 1.0f, 0.5f};
    const ShadeOptions o = darkRoom(l);
    const EmitterLights lights = EmitterLights::build(world, o.materials);
    EXPECT_EQ(lights.faceCount(), 6);  // a lamp in the air: every face open
    // Under the centre (the bottom face alone), beside it (a side face too), further out (every
    // face's unoccluded irradiance above twice the floor: no fade).
    for (const Vec3d p : {Vec3d{12.5, 1, 12.5}, Vec3d{13.7, 1, 12.2}, Vec3d{15.0, 1, 14.0},
                          Vec3d{9.1, 1, 12.5}, Vec3d{12.5, 1, 20.0}}) {
        const double truth = quadratureIrradiance(p, lamp);
        const Rgb e = floorIrradiance(lights, world, o, p);
        std::printf("  (%.1f, %.1f): E/L %.6f, quadrature %.6f, relative %.2e\n", p.x, p.z,
                    e.g / l.g, truth, std::abs(e.g / l.g - truth) / truth);
        // Float arithmetic and the quadrature's own error (< 1e-5 here) are far inside this.
        EXPECT_NEAR(e.g / l.g, truth, 1e-4 * truth + 1e-7);
        EXPECT_NEAR(e.r / l.r, truth, 1e-4 * truth + 1e-7);
        EXPECT_NEAR(e.b / l.b, truth, 1e-4 * truth + 1e-7);
    }
    // Far out the faces fade: each loses at most twice the floor of its largest channel, never
    // more light than the truth.
    const Vec3d far{2.0, 1, 3.0};
    const double truth = quadratureIrradiance(far, lamp);
    const double e = floorIrradiance(lights, world, o, far).g / l.g;
    std::printf("  far (2, 3): E/L %.6f, quadrature %.6f\n", e, truth);
    EXPECT_LE(e, truth * (1 + 1e-4));
    EXPECT_GE(e, truth - 3 * 2 * double(lights.floor()) / 1.5);
    EXPECT_GT(e, 0.5 * truth);
}

TEST(EmitterLight, TheRayCasterShowsTheFloorLitByTheLamp) {
    VoxelWorld world = floorWorld();
    world.set(12, 4, 12, kLamp);
    ShadeOptions o = darkRoom(Rgb(2.0f));
    const EmitterLights lights = EmitterLights::build(world, o.materials);
    o.emitterLights = &lights;
    // Looking down at the floor beside the lamp: radiance = albedo / pi * E.
    const Vec3d p{14.5, 1, 12.5};
    const Rgb seen = shadeRay(world, {p + Vec3d{0, 6, 0}, {0, -1, 0}}, o);
    const double expected = 2.0 / kPi * quadratureIrradiance(p, {12, 4, 12});
    EXPECT_NEAR(seen.g, expected, 1e-4 * expected);
    // Off: the floor is black, as before the light existed; the lamp itself still shows.
    o.emitterLight = false;
    EXPECT_EQ(shadeRay(world, {p + Vec3d{0, 6, 0}, {0, -1, 0}}, o).maxComponent(), 0.0f);
    EXPECT_NEAR(shadeRay(world, {{12.5, 10, 12.5}, {0, -1, 0}}, o).g, 2.0f, 1e-6f);
}

TEST(EmitterLight, APathSpendsItsBudgetOfRays) {
    VoxelWorld world = floorWorld();
    for (int x = 10; x < 13; ++x) {
        for (int z = 10; z < 13; ++z) world.set(x, 3, z, kLamp);  // a 3 x 3 lamp panel
    }
    const ShadeOptions o = darkRoom(Rgb(1.0f));
    const EmitterLights lights = EmitterLights::build(world, o.materials);
    // 9 faces below, 9 above, 3 on each side: one rectangle each.
    EXPECT_EQ(lights.faceCount(), 30);
    EXPECT_EQ(lights.emitterCount(), 6);
    EmitterLights::Surface s;
    s.point = {14.5, 1, 11.5};
    s.faceNormal = {0, 1, 0};
    s.shadingNormal = {0, 1, 0};
    s.view = {0, 1, 0};
    s.diffuseAlbedo = Rgb(1.0f);
    // Two rectangles face the point, the bottom (9 faces) the stronger and the +x side (3):
    // 2 x 4 rays spent; the bottom alone when only 6 rays are left, nothing with 3 (fewer than
    // an emitter takes).
    int full = kEmitterPathRays, six = 6, none = 3;
    const Rgb all = lights.light(world, nullptr, s, o, 4, full);
    const Rgb bottom = lights.light(world, nullptr, s, o, 4, six);
    EXPECT_EQ(full, kEmitterPathRays - 8);
    EXPECT_EQ(six, 2);
    EXPECT_GT(bottom.g, 0.5f * all.g);
    EXPECT_LT(bottom.g, all.g);
    EXPECT_EQ(lights.light(world, nullptr, s, o, 4, none).maxComponent(), 0.0f);
    EXPECT_EQ(none, 3);
}

// A lamp panel larger than the 16 emitters a point keeps: its coplanar faces are merged into
// rectangles, each lit exactly, so the floor takes the light of the whole panel.
TEST(EmitterLight, ALargePanelLightsWithAllItsFaces) {
    VoxelWorld world = floorWorld();
    const Int3 lo{4, 6, 6}, hi{20, 7, 18};  // 16 x 1 x 12 voxels, its bottom 6 above the floor
    for (int x = lo.x; x < hi.x; ++x) {
        for (int z = lo.z; z < hi.z; ++z) world.set(x, lo.y, z, kLamp);
    }
    const ShadeOptions o = darkRoom(Rgb(1.0f));
    const EmitterLights lights = EmitterLights::build(world, o.materials);
    // 192 faces below, 192 above, 2 x 16 + 2 x 12 on the sides.
    EXPECT_EQ(lights.faceCount(), 440);
    // 4 x 3 rectangles of 4 x 4 below and above, sides in runs of 4.
    EXPECT_EQ(lights.emitterCount(), 12 + 12 + 4 + 4 + 3 + 3);
    for (const Vec3d p :
         {Vec3d{12.0, 1, 12.0}, Vec3d{5.5, 1, 7.25}, Vec3d{2.0, 1, 12.0}, Vec3d{21.5, 1, 12.0}}) {
        const double truth = quadratureIrradiance(p, lo, hi, 64);
        const Rgb e = floorIrradiance(lights, world, o, p);
        std::printf("  (%.2f, %.2f): E/L %.6f, quadrature %.6f, relative %.2e\n", p.x, p.z, e.g,
                    truth, std::abs(e.g - truth) / truth);
        // Every rectangle the point sees is kept (at most 16 face it) and none fades here.
        EXPECT_NEAR(e.g, truth, 2e-4 * truth);
    }
}

// A receiving face across the plane of a panel (a wall under it) takes only the part of each
// rectangle in front of it: the rest lies behind the wall.
TEST(EmitterLight, AWallUnderAPanelTakesOnlyThePartInFront) {
    VoxelWorld world = floorWorld();
    for (int x = 4; x < 12; ++x) {
        for (int z = 8; z < 12; ++z) world.set(x, 8, z, kLamp);  // 8 x 4 panel at y = 8
    }
    for (int y = 1; y < 8; ++y) {
        for (int z = 0; z < 24; ++z) world.set(6, y, z, kWhite);  // a wall under it at x = 6
    }
    const ShadeOptions o = darkRoom(Rgb(1.0f));
    const EmitterLights lights = EmitterLights::build(world, o.materials);
    EmitterLights::Surface s;
    s.point = {7.0, 4.5, 10.0};  // on the wall's +x face
    s.faceNormal = {1, 0, 0};
    s.shadingNormal = {1, 0, 0};
    s.view = {1, 0, 0};
    s.diffuseAlbedo = Rgb(float(kPi));
    int budget = kEmitterPathRays;
    const double e = lights.light(world, nullptr, s, o, 4, budget).g;
    // The truth: the part of the panel's bottom with x > 7 (x in [7, 12)), seen from p with
    // normal +x, by the midpoint rule.
    double truth = 0;
    const int n = 200;
    for (int i = 0; i < 5 * n; ++i) {
        for (int j = 0; j < 4 * n; ++j) {
            const Vec3d q{7.0 + (i + 0.5) / n, 8.0, 8.0 + (j + 0.5) / n};
            const Vec3d d = q - s.point;
            const double r2 = dot(d, d);
            truth += (d.x / std::sqrt(r2)) * (d.y / std::sqrt(r2)) / r2 / (double(n) * n);
        }
    }
    std::printf("  wall: E/L %.6f, quadrature %.6f\n", e, truth);
    EXPECT_NEAR(e, truth, 2e-4 * truth);
}

TEST(EmitterLight, OneVoxelWallCastsAFullShadow) {
    VoxelWorld world = floorWorld();
    world.set(8, 1, 12, kLamp);
    // A wall at x = 12 across the whole world, floor to top: nothing of the lamp passes.
    for (int y = 1; y < 24; ++y) {
        for (int z = 0; z < 24; ++z) world.set(12, y, z, kWhite);
    }
    ShadeOptions o = darkRoom(Rgb(3.0f));
    const EmitterLights lights = EmitterLights::build(world, o.materials);
    EXPECT_EQ(lights.faceCount(), 5);  // the bottom face lies on the floor
    // (Points exactly on the wall's edge are the DDA's: a ray started on two faces at once.)
    for (const Vec3d p : {Vec3d{13.02, 1, 12.5}, Vec3d{14.5, 1, 12.5}, Vec3d{20.5, 1, 3.5}}) {
        EXPECT_EQ(floorIrradiance(lights, world, o, p).maxComponent(), 0.0f) << p.x;
    }
    EXPECT_GT(floorIrradiance(lights, world, o, {10.5, 1, 12.5}).g, 0.01f);
    // The wall's own side facing the lamp is lit, its back is not.
    EmitterLights::Surface front;
    front.point = {12.0, 2.5, 12.5};
    front.faceNormal = {-1, 0, 0};
    front.shadingNormal = {-1, 0, 0};
    front.view = {-1, 0, 0};
    front.diffuseAlbedo = Rgb(1.0f);
    int budget = kEmitterPathRays;
    EXPECT_GT(lights.light(world, nullptr, front, o, 4, budget).g, 0.0f);
    EmitterLights::Surface back = front;
    back.point.x = 13.0;
    back.faceNormal = {1, 0, 0};
    back.shadingNormal = {1, 0, 0};
    budget = kEmitterPathRays;
    EXPECT_EQ(lights.light(world, nullptr, back, o, 4, budget).maxComponent(), 0.0f);
}

TEST(EmitterLight, GlassPassesPartOfTheLight) {
    VoxelWorld world = floorWorld();
    world.set(8, 3, 12, kLamp);
    const Vec3d p{14.5, 1, 12.5};
    ShadeOptions o = darkRoom(Rgb(3.0f));
    const Rgb open = floorIrradiance(EmitterLights::build(world, o.materials), world, o, p);
    // A glass wall across the world between the lamp and the point.
    for (int y = 1; y < 24; ++y) {
        for (int z = 0; z < 24; ++z) world.set(11, y, z, kGlass);
    }
    const EmitterLights lights = EmitterLights::build(world, o.materials);
    const Rgb through = floorIrradiance(lights, world, o, p);
    std::printf("  open %.5f, through glass %.5f (ratio %.3f)\n", open.g, through.g,
                through.g / open.g);
    // Two Fresnel interfaces (about 4% each near normal incidence) and absorption exp(-0.2 d),
    // d >= 1: the share lies well between none and all.
    EXPECT_GT(through.g, 0.5f * open.g);
    EXPECT_LT(through.g, 0.85f * open.g);
    // Without refraction glass is opaque: no light at all.
    o.refraction = false;
    EXPECT_EQ(floorIrradiance(lights, world, o, p).maxComponent(), 0.0f);
}

TEST(EmitterLight, RendersFiniteWhereThePointTouchesTheLamp) {
    VoxelWorld world = floorWorld();
    world.set(12, 1, 12, kLamp);  // standing on the floor: its side faces meet it
    world.set(13, 1, 12, kLamp);
    ShadeOptions o = darkRoom(Rgb(5.0f));
    o.specular = ShadeOptions::Specular::Ggx;
    for (const Vec3d p :
         {Vec3d{12.0, 1, 12.0}, Vec3d{14.0, 1, 12.5}, Vec3d{11.0, 1, 13.0}, Vec3d{14.0, 1, 13.0}}) {
        const Rgb e = floorIrradiance(EmitterLights::build(world, o.materials), world, o, p);
        EXPECT_TRUE(std::isfinite(e.r) && std::isfinite(e.g) && std::isfinite(e.b)) << p.x;
        EXPECT_GE(e.g, 0.0f);
    }
    const Camera camera = Camera::lookAt({12.5, 3.0, 9.0}, {12.5, 1.0, 12.0}, 70, 48, 32).value();
    const Image image = render(world, camera, o);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Rgb c = image.rgb(x, y);
            ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
        }
    }
}

TEST(EmitterLight, SceneFieldsAreReadAndChecked) {
    const std::string head =
        R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
            "camera": {"position": [0, 0, 0]}, "render": )";
    auto scene = parseVoxelScene(head + R"({"emitter_light": false, "emitter_rays": 9}})", "s");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_FALSE(scene->shading.emitterLight);
    EXPECT_EQ(scene->shading.emitterRays, 9);
    scene = parseVoxelScene(head + "{}}", "s");
    ASSERT_TRUE(scene.ok());
    EXPECT_TRUE(scene->shading.emitterLight);
    EXPECT_EQ(scene->shading.emitterRays, 4);
    for (const char* bad : {R"({"emitter_rays": 0}})", R"({"emitter_rays": 65}})",
                            R"({"emitter_rays": 2.5}})", R"({"emitter_light": 1}})"}) {
        auto s = parseVoxelScene(head + bad, "bad.json");
        ASSERT_FALSE(s.ok()) << bad;
        const std::string field = std::string(bad).find("rays") != std::string::npos
                                      ? "render.emitter_rays"
                                      : "render.emitter_light";
        EXPECT_NE(s.error().message().find(field), std::string::npos) << s.error().message();
        EXPECT_NE(s.error().message().find("bad.json"), std::string::npos) << s.error().message();
    }
}

}  // namespace
}  // namespace luxel::voxel
