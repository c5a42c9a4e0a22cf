// Physical lighting of voxel surfaces against analytic values: a lit face, a glass slab at
// normal incidence, total internal reflection, a lossless dielectric in a uniform sky (white
// furnace), a metal mirror, rough ground without mirror images, emission.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/shaders/shared/optics.h"
#include "luxel/core/tonemap.h"
#include "luxel/voxel/shading.h"
#include "voxel/shading_physical.h"

namespace luxel::voxel {
namespace {

constexpr float kPi = 3.14159265358979f;

void expectNear(Rgb a, Rgb b, float eps) {
    EXPECT_NEAR(a.r, b.r, eps);
    EXPECT_NEAR(a.g, b.g, eps);
    EXPECT_NEAR(a.b, b.b, eps);
}

ShadeOptions physical() {
    ShadeOptions o;
    o.lighting = ShadeOptions::Lighting::Physical;
    o.textures = false;
    o.specular = ShadeOptions::Specular::None;
    return o;
}

// A 24^3 world with a white floor at y = 0.
VoxelWorld floorWorld() {
    VoxelWorld world = VoxelWorld::create({24, 24, 24}, 8).value();
    for (int z = 0; z < 24; ++z) {
        for (int x = 0; x < 24; ++x) world.set(x, 0, z, {255, 255, 255, 255});
    }
    return world;
}

TEST(Surfaces, LitFaceIsLambertPlusSkyAmbient) {
    const VoxelWorld world = floorWorld();
    ShadeOptions o = physical();
    Material m = defaultMaterial();
    m.albedo = {0.5f, 0.4f, 0.3f};
    m.ior = 1.0f;  // no Fresnel reflection: the diffuse terms alone
    ASSERT_TRUE(o.materials.setPlain(m).ok());
    o.sunDirection = {0.6f, 0.8f, 0.0f};
    o.sunIrradiance = {3.0f, 2.0f, 1.0f};
    o.skyAmbient = 0.4f;
    const Ray down{{11.3, 10.0, 12.6}, {0, -1, 0}};
    const Rgb expected = m.albedo * (o.sunIrradiance * (0.8f / kPi)) +
                         m.albedo * o.skyTop * o.skyAmbient;  // sky(N = up) = skyTop
    expectNear(shadeRay(world, down, o), expected, 1e-5f);
    // A column between the point and the sun leaves the sky ambient only.
    VoxelWorld shaded = world;
    for (int y = 1; y < 6; ++y) shaded.set(13, y, 12, {255, 255, 255, 255});
    expectNear(shadeRay(shaded, down, o), m.albedo * o.skyTop * o.skyAmbient, 1e-5f);
    // The GGX highlight adds light; N.L and the visibility scale it (here a lit point).
    o.specular = ShadeOptions::Specular::Ggx;
    m.ior = 1.5f;
    ASSERT_TRUE(o.materials.setPlain(m).ok());
    EXPECT_GT(shadeRay(world, down, o).r, expected.r);
}

TEST(Surfaces, GlassSlabTransmitsFresnelSquaredTimesBeerLambert) {
    VoxelWorld world = VoxelWorld::create({16, 16, 16}, 8).value();
    ShadeOptions o = physical();
    Material glass;
    glass.name = "glass";
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    glass.ior = 1.5f;
    glass.absorption = {0.1f, 0.2f, 0.3f};
    ASSERT_TRUE(o.materials.setSlot(0, glass).ok());
    for (int z = 0; z < 16; ++z) {
        for (int y = 5; y < 8; ++y) {  // 3 voxels thick
            for (int x = 0; x < 16; ++x) world.set(x, y, z, {255, 255, 255, alphaForSlot(0)});
        }
    }
    o.maxReflections = 2;  // in and out: no internal bounces
    o.skyTop = {0.2f, 0.3f, 0.9f};
    o.skyHorizon = {0.9f, 0.8f, 0.7f};
    const float f = 0.04f;  // ((1.5 - 1) / 2.5)^2
    const Rgb transmitted =
        Rgb(std::exp(-0.3f), std::exp(-0.6f), std::exp(-0.9f)) * ((1 - f) * (1 - f));
    // Looking down: the top face mirrors the sky straight up, the slab passes the sky below
    // (the horizon colour).
    const Ray down{{7.3, 12.0, 8.6}, {0, -1, 0}};
    for (auto model : {ShadeOptions::FresnelModel::Exact, ShadeOptions::FresnelModel::Schlick}) {
        o.fresnel = model;
        expectNear(shadeRay(world, down, o), o.skyTop * f + o.skyHorizon * transmitted, 1e-5f);
    }
    // Without refraction the glass is opaque, as if it did not transmit.
    o.refraction = false;
    const Rgb opaque = shadeRay(world, down, o);
    glass.transmission = 0.0f;
    ASSERT_TRUE(o.materials.setSlot(0, glass).ok());
    o.refraction = true;
    expectNear(opaque, shadeRay(world, down, o), 1e-6f);
}

TEST(Surfaces, ExitBeyondTheCriticalAngleReflectsTotally) {
    // Inside glass (1.5) towards a +x face: 30 degrees from the normal refracts, 50 does not
    // (critical angle 41.8 degrees).
    const auto at = [](double degrees) {
        const double a = degrees * 3.14159265358979 / 180.0;
        return Vec3d{std::cos(a), -std::sin(a), 0.0};
    };
    for (auto model : {ShadeOptions::FresnelModel::Exact, ShadeOptions::FresnelModel::Schlick}) {
        const ExitSplit grazing = splitAtExit(at(50), {1, 0, 0}, 1.5f, model);
        EXPECT_TRUE(grazing.total);
        EXPECT_EQ(grazing.reflectance, 1.0f);
        EXPECT_NEAR(grazing.reflected.x, -at(50).x, 1e-6);
        EXPECT_NEAR(grazing.reflected.y, at(50).y, 1e-6);
        const ExitSplit steep = splitAtExit(at(30), {1, 0, 0}, 1.5f, model);
        EXPECT_FALSE(steep.total);
        EXPECT_LT(steep.reflectance, 0.1f);
        // Snell: sin(theta_t) = 1.5 sin(30 degrees) = 0.75.
        EXPECT_NEAR(-steep.refracted.y, 0.75, 1e-5);
    }
    const ExitSplit normal =
        splitAtExit({0, 0, -1}, {0, 0, -1}, 1.5f, ShadeOptions::FresnelModel::Exact);
    EXPECT_NEAR(normal.reflectance, 0.04f, 1e-6f);
    EXPECT_NEAR(normal.refracted.z, -1.0, 1e-9);

    // In a scene: a ray entering a glass bar's top at 60 degrees meets both sides at 54.7
    // degrees and reflects totally, then leaves through the bottom; the sides pass nothing. With
    // a black sky above the horizon and a white one below, no light is lost on that path.
    VoxelWorld world = VoxelWorld::create({32, 32, 32}, 8).value();
    ShadeOptions o = physical();
    Material glass;
    glass.name = "glass";
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    ASSERT_TRUE(o.materials.setSlot(0, glass).ok());
    for (int z = 0; z < 32; ++z) {
        for (int y = 10; y < 20; ++y) {
            for (int x = 10; x < 14; ++x) world.set(x, y, z, {255, 255, 255, alphaForSlot(0)});
        }
    }
    o.skyTop = Rgb(0.0f);
    o.skyHorizon = Rgb(1.0f);
    o.maxReflections = 4;  // in, two total reflections, out
    const double s60 = std::sin(60.0 * 3.14159265358979 / 180.0);
    const Ray in{{12.2 - s60 * 10, 25.0, 16.5}, {s60, -0.5, 0.0}};
    const MediumExit side = walkMedium(world, {12, 19, 16}, {12.2, 20.0, 16.5},
                                       normalize(Vec3d{s60 / 1.5, -std::sqrt(1 - 0.75 / 2.25), 0}));
    EXPECT_EQ(side.outward, (Int3{1, 0, 0}));
    EXPECT_FALSE(side.intoSolid);
    // Entering: 1 - F(60 degrees); leaving through the bottom at 35.3 degrees: 1 - F again.
    const float cos60 = 0.5f;
    const float fIn = gpu::shared::fresnelDielectricExact(cos60, 1.0f, 1.5f);
    const float fOut =
        gpu::shared::fresnelDielectricExact(std::sqrt(1 - 0.75f / 2.25f), 1.5f, 1.0f);
    // Plus the entry face's mirror image of the sky, half way up its gradient at 30 degrees.
    const Vec3d mirrored{in.direction.x, -in.direction.y, 0.0};
    EXPECT_NEAR(shadeRay(world, in, o).r, (1 - fIn) * (1 - fOut) + fIn * skyColor(mirrored, o).r,
                2e-5f);
}

TEST(Surfaces, LosslessGlassInAUniformSkyIsInvisible) {
    // White furnace: whatever the path (Fresnel splits, total reflections), every bit of weight
    // ends in the sky, so the radiance is the sky's up to the paths cut by the budget and the
    // 1/255 weight threshold.
    VoxelWorld world = VoxelWorld::create({32, 32, 32}, 8).value();
    ShadeOptions o = physical();
    o.sunIrradiance = Rgb(0.0f);
    o.skyTop = o.skyHorizon = Rgb(1.0f);
    o.maxReflections = 16;
    Material glass;
    glass.name = "glass";
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    ASSERT_TRUE(o.materials.setSlot(0, glass).ok());
    // A cube: every face flat, so the paths end within the budget (a voxel sphere's staircase
    // lets rays leave and re-enter many times, each crossing spending budget).
    for (int z = 10; z < 22; ++z) {
        for (int y = 10; y < 22; ++y) {
            for (int x = 10; x < 22; ++x) world.set(x, y, z, {255, 255, 255, alphaForSlot(0)});
        }
    }
    int hits = 0;
    for (int i = 0; i < 64; ++i) {
        const Ray ray{
            {16.0 - 14 * 0.35 + 1.41 * (i % 8 - 3.5), 30.0, 16.0 - 14 * 0.4 + 1.37 * (i / 8 - 3.5)},
            {0.35, -1.0, 0.4}};
        const Rgb c = shadeRay(world, ray, o);
        EXPECT_NEAR(c.r, 1.0f, 0.02f) << i;
        EXPECT_LE(c.r, 1.0f + 1e-5f) << i;
        if (castRay(world, ray).hit) ++hits;
    }
    EXPECT_GT(hits, 20);
}

TEST(Surfaces, MetalMirrorReflectsTheSky) {
    VoxelWorld world = floorWorld();
    ShadeOptions o = physical();
    o.specular = ShadeOptions::Specular::Ggx;
    o.sunDirection = {-0.5f, 1.0f, -0.5f};  // far from the mirror direction
    Material metal;
    metal.metallic = 1.0f;
    metal.roughness = 0.0f;
    ASSERT_TRUE(o.materials.setPlain(metal).ok());
    const Ray ray{{4.3, 6.0, 4.6}, normalize(Vec3d{0.3, -1.0, 0.5})};
    const Vec3d reflected{ray.direction.x, -ray.direction.y, ray.direction.z};
    expectNear(shadeRay(world, ray, o), skyColor(reflected, o), 1e-4f);
    // A gold-coloured metal tints it by Schlick with F0 = its colour.
    world.set(int(4.3 + 5 * 0.3), 0, int(4.6 + 5 * 0.5), {255, 200, 60, 255});
    const Rgb gold = shadeRay(world, ray, o);
    EXPECT_LT(gold.b, 0.5f * skyColor(reflected, o).b);
}

TEST(Surfaces, RoughGroundMirrorsNoTower) {
    // A floor point whose mirror direction meets a glowing tower: rough ground looks the same
    // with and without the tower, smooth ground does not.
    const VoxelWorld plain = floorWorld();
    VoxelWorld tower = plain;
    for (int y = 1; y < 20; ++y) {
        for (int x = 8; x < 16; ++x) tower.set(x, y, 20, {255, 255, 255, alphaForSlot(0)});
    }
    ShadeOptions o = physical();
    Material lamp = defaultMaterial();
    lamp.emission = Rgb(10.0f);
    ASSERT_TRUE(o.materials.setSlot(0, lamp).ok());
    o.specular = ShadeOptions::Specular::Ggx;
    o.sunDirection = {0.0f, 1.0f, 0.2f};  // the tower shades z > 20, not the viewed point
    o.skyTop = o.skyHorizon = Rgb(0.05f);
    const Ray ray{{12.3, 8.0, 2.0}, normalize(Vec3d{0.0, -1.0, 1.0})};  // floor at z = 9
    ASSERT_TRUE(castRay(tower, {{12.3, 0.9999, 9.0}, {0, 1, 1}}).hit);  // the mirror sees it
    expectNear(shadeRay(tower, ray, o), shadeRay(plain, ray, o), 1e-6f);
    Material smooth = defaultMaterial();
    smooth.roughness = 0.05f;
    ASSERT_TRUE(o.materials.setPlain(smooth).ok());
    EXPECT_GT(shadeRay(tower, ray, o).r, shadeRay(plain, ray, o).r + 0.2f);
}

TEST(Surfaces, EmissionAddsItsRadiance) {
    VoxelWorld world = floorWorld();
    ShadeOptions o = physical();
    const Ray down{{11.3, 10.0, 12.6}, {0, -1, 0}};
    const Rgb base = shadeRay(world, down, o);
    Material lamp = defaultMaterial();
    lamp.emission = {5.0f, 4.0f, 3.0f};
    ASSERT_TRUE(o.materials.setPlain(lamp).ok());
    expectNear(shadeRay(world, down, o), base + lamp.emission, 1e-5f);
}

TEST(Surfaces, ClassicLightingIgnoresMaterials) {
    const VoxelWorld world = floorWorld();
    ShadeOptions o;
    const Ray down{{11.3, 10.0, 12.6}, {0, -0.8, 0.3}};
    const Rgb before = shadeRay(world, down, o);
    Material lamp = defaultMaterial();
    lamp.emission = Rgb(5.0f);
    lamp.metallic = 1.0f;
    ASSERT_TRUE(o.materials.setPlain(lamp).ok());
    EXPECT_EQ(shadeRay(world, down, o), before);
}

}  // namespace
}  // namespace luxel::voxel
