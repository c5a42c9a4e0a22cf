// Tests for voxel shading: sky, face term, shadows, reflections and deterministic rendering.
#include "luxel/voxel/shading.h"
#include "luxel/voxel/render_image.h"

#include <gtest/gtest.h>

#include <cmath>

#include "luxel/core/parallel.h"

namespace luxel::voxel {
namespace {

// A 16 x 8 x 16 world: a grey floor (y = 0) and a red column at (8, 1..3, 8).
VoxelWorld floorWorld() {
    VoxelWorld world = VoxelWorld::create({16, 8, 16}, 8).value();
    for (int z = 0; z < 16; ++z) {
        for (int x = 0; x < 16; ++x) world.set(x, 0, z, {180, 180, 180, 255});
    }
    for (int y = 1; y <= 3; ++y) world.set(8, y, 8, {200, 40, 40, 255});
    return world;
}

void expectNear(Rgb a, Rgb b, float eps = 1e-5f) {
    EXPECT_NEAR(a.r, b.r, eps);
    EXPECT_NEAR(a.g, b.g, eps);
    EXPECT_NEAR(a.b, b.b, eps);
}

TEST(VoxelShadingTest, UnityTracerFaceFactor) {
    // The Unity tracer's factors for its light (0, 1, 0.5): top 1 (clamped), +z .85, sides .6, -z
    // .35, bottom .1.
    const Vec3 sun{0.0f, 1.0f, 0.5f};
    EXPECT_FLOAT_EQ(faceFactor({0, 1, 0}, sun, 0.1f, false), 1.0f);
    EXPECT_FLOAT_EQ(faceFactor({0, 0, 1}, sun, 0.1f, false), 0.85f);
    EXPECT_FLOAT_EQ(faceFactor({1, 0, 0}, sun, 0.1f, false), 0.6f);
    EXPECT_FLOAT_EQ(faceFactor({0, 0, -1}, sun, 0.1f, false), 0.35f);
    EXPECT_FLOAT_EQ(faceFactor({0, -1, 0}, sun, 0.1f, false), 0.1f);
    EXPECT_FLOAT_EQ(faceFactor({0, 1, 0}, sun, 0.1f, true), 0.6f);
}

TEST(VoxelShadingTest, PixelSeeingSkyGetsSkyColour) {
    const VoxelWorld world = floorWorld();
    ShadeOptions options;
    const Camera camera = Camera::create({4.5, 4.0, 4.5}, 0, 60, 60, 16, 12).value();
    const Ray ray = camera.primaryRay(8, 0);
    expectNear(shadePixel(world, camera, 8, 0, options), skyColor(ray.direction, options));
    // Straight up is skyTop; at or below the horizon skyHorizon.
    expectNear(skyColor({0, 2, 0}, options), options.skyTop);
    expectNear(skyColor({1, 0, 0}, options), options.skyHorizon);
    expectNear(skyColor({1, -1, 0}, options), options.skyHorizon);
    // Outside the world and missing it: sky too.
    const Ray away{{-10, 4, 4}, {-1, 0.2, 0}};
    expectNear(shadeRay(world, away, options), skyColor(away.direction, options));
}

TEST(VoxelShadingTest, ShadowedFloorIsDarkerThanLitFloor) {
    const VoxelWorld world = floorWorld();
    ShadeOptions options;
    options.textures = false;
    options.maxReflections = 0;
    // Sun (0, 1, 0.5): the column (y 1..4) shades floor cells x = 8, z in [6.5, 8].
    const Rgb shadowed = shadeRay(world, {{8.5, 7.5, 7.0}, {0, -1, 0}}, options);
    const Rgb lit = shadeRay(world, {{8.5, 7.5, 4.0}, {0, -1, 0}}, options);
    const Rgb litSide = shadeRay(world, {{3.5, 7.5, 7.0}, {0, -1, 0}}, options);
    EXPECT_LT(shadowed.r, lit.r);
    EXPECT_NEAR(shadowed.r / lit.r, 0.6f, 1e-5f);
    expectNear(lit, litSide);
    options.shadows = false;
    expectNear(shadeRay(world, {{8.5, 7.5, 7.0}, {0, -1, 0}}, options), lit);
}

TEST(VoxelShadingTest, ReflectionModesWeightAsDocumented) {
    const VoxelWorld world = floorWorld();
    ShadeOptions options;
    const Ray down{{3.5, 6.0, 3.5}, {0, -1, 0}};  // floor, then straight up into the sky
    options.maxReflections = 0;
    const Rgb local = shadeRay(world, down, options);
    options.reflectionMode = ShadeOptions::ReflectionMode::EnergyConserving;
    expectNear(shadeRay(world, down, options), local);  // no bounces: both modes agree
    options.maxReflections = 1;
    const Rgb sky = options.skyTop;
    expectNear(shadeRay(world, down, options), local * 0.7f + sky * 0.3f);
    options.materialReflectivity = [](const Voxel&) { return 0.5f; };
    expectNear(shadeRay(world, down, options), local * 0.5f + sky * 0.5f);
    options.reflectionMode = ShadeOptions::ReflectionMode::RunningAverage;
    expectNear(shadeRay(world, down, options), local * (2.0f / 3.0f) + sky * (1.0f / 3.0f));
    options.maxReflections = 5;  // the sky ends the chain: same result
    expectNear(shadeRay(world, down, options), local * (2.0f / 3.0f) + sky * (1.0f / 3.0f));
}

TEST(VoxelShadingTest, ReflectionsChangeTheImage) {
    const VoxelWorld world = floorWorld();
    const Camera camera = Camera::lookAt({2.5, 5.0, 1.5}, {8.5, 1.5, 8.5}, 60, 32, 24).value();
    ShadeOptions options;
    options.maxReflections = 0;
    const Image none = render(world, camera, options);
    options.maxReflections = 2;
    const Image seed = render(world, camera, options);
    options.reflectionMode = ShadeOptions::ReflectionMode::EnergyConserving;
    const Image energy = render(world, camera, options);
    EXPECT_NE(none, seed);
    EXPECT_NE(seed, energy);
    EXPECT_NE(none, energy);
    for (std::size_t i = 0; i < energy.size(); ++i) {
        ASSERT_TRUE(std::isfinite(energy.data()[i]));
        ASSERT_GE(energy.data()[i], 0.0f);
    }
}

TEST(VoxelShadingTest, RenderIsDeterministicAcrossThreadCounts) {
    const VoxelWorld world = floorWorld();
    const Camera camera = Camera::lookAt({1.5, 6.0, 1.5}, {8.5, 1.0, 8.5}, 70, 40, 30).value();
    ShadeOptions options;
    Image one, two;
    {
        ThreadLimit limit(1);
        one = render(world, camera, options);
    }
    {
        ThreadLimit limit(2);
        two = render(world, camera, options);
    }
    EXPECT_EQ(one, two);
    EXPECT_EQ(one.width(), 40);
    EXPECT_EQ(one.height(), 30);
    EXPECT_EQ(one.channels(), 3);
    expectNear(one.rgb(7, 11), shadePixel(world, camera, 7, 11, options), 0.0f);
}

TEST(VoxelShadingTest, TextureIsSubtleAndDeterministic) {
    ShadeOptions options;
    Hit hit;
    hit.hit = true;
    hit.voxel = {3, 0, 5};
    hit.normal = {0, 1, 0};
    float lo = 1.0f, hi = 0.0f;
    for (int i = 0; i < 64; ++i) {
        hit.u = (i % 8 + 0.5f) / 8.0f;
        hit.v = (i / 8 + 0.5f) / 8.0f;
        const float f = textureFactor(hit, options);
        EXPECT_EQ(f, textureFactor(hit, options));
        lo = std::min(lo, f);
        hi = std::max(hi, f);
    }
    EXPECT_GE(lo, 1.0f - options.textureStrength);
    EXPECT_LE(hi, 1.0f);
    EXPECT_GT(hi - lo, 0.02f);
}

}  // namespace
}  // namespace luxel::voxel
