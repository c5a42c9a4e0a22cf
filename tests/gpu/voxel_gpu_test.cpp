// The GPU voxel renderer against the CPU one (render() in shading.h) on whatever Vulkan device is
// present (lavapipe on CPU-only machines; skipped, saying why, without one). The CPU traces in
// double and the GPU in float, so a ray grazing a voxel edge can pick the other voxel: the
// textured terrain bounds the share of such pixels; simple axis-aligned scenes must agree
// exactly at 8 bits. Validation layers are on and any message fails the test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gpu/shaders/shared/voxel_layout.h"
#include "luxel/core/tonemap.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"
#include "support/display_parity.h"
#include "support/gpu_test_context.h"

namespace luxel::voxel {
namespace {

using test::compareDisplay;
using test::Parity;
using test::printParity;

// Slot 0: bricks-like opaque tint; slot 1: leaves with every other texel a cutout.
TextureSet testTextures() {
    TextureSet set;
    Texture opaque{"opaque", 4, 4, {}, 0.0f};
    for (int i = 0; i < 16; ++i) {
        opaque.texels.push_back({0.4f + 0.1f * (i % 4), 0.6f, 0.3f + 0.05f * (i / 4), 1.0f});
    }
    Texture holes{"holes", 4, 4, {}, std::nullopt};
    for (int i = 0; i < 16; ++i) {
        holes.texels.push_back({0.3f, 0.8f, 0.2f, ((i + i / 4) % 2) ? 0.0f : 1.0f});
    }
    EXPECT_TRUE(set.add(opaque).ok());
    EXPECT_TRUE(set.add(holes).ok());
    return set;
}

// A 96 x 48 x 96 terrain with a mirror-ish sphere, a textured wall and a cutout canopy.
VoxelWorld texturedTerrain() {
    VoxelWorld world = VoxelWorld::create({96, 48, 96}, 16).value();
    TerrainOptions t;
    t.seed = 11;
    t.frequency = 0.02;
    EXPECT_TRUE(generateTerrain(world, t).ok());
    addSphere(world, {48, 30, 50}, 7, Voxel{230, 230, 240, 255});
    addBox(world, {20, 10, 60}, {60, 26, 62}, Voxel{255, 255, 255, alphaForSlot(0)});
    addBox(world, {30, 28, 20}, {70, 30, 45}, Voxel{255, 255, 255, alphaForSlot(1)});
    return world;
}

ShadeOptions terrainShading(ShadeOptions::ReflectionMode mode) {
    ShadeOptions o;
    o.sunDirection = {0.4f, 1.0f, 0.3f};
    o.maxReflections = 2;
    o.reflectionMode = mode;
    o.reflectivity = 0.3f;
    return o;
}

TEST(VoxelGpu, MemoryEstimateAndRefusal) {
    // 512^3 RGBA in 32^3 chunks: 512 MiB of voxels, 32 MiB of brick masks and reach (16 bytes
    // per 4^3 brick: the mask and a reach byte per octant), plus small tables and the image.
    const std::uint64_t big = estimateVoxelGpuMemory({512, 512, 512}, 32, nullptr, 0, 0);
    EXPECT_GE(big, std::uint64_t{544} << 20);
    EXPECT_LT(big, (std::uint64_t{544} << 20) + (1u << 20));
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = VoxelWorld::create({64, 64, 64}, 16).value();
    auto refused = VoxelGpuRenderer::create(*context, world, nullptr, 1u << 20);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message().find("voxel world 64x64x64 needs"), std::string::npos)
        << refused.error().message();
    EXPECT_NE(refused.error().message().find("the budget is 1.0 MiB"), std::string::npos)
        << refused.error().message();
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// Axis-aligned boxes, axis-aligned sun, camera looking along an axis: every pixel agrees.
TEST(VoxelGpu, SimpleAxisAlignedSceneMatchesExactly) {
    LUXEL_REQUIRE_GPU(context);
    VoxelWorld world = VoxelWorld::create({32, 16, 32}, 8).value();
    addBox(world, {0, 0, 0}, {32, 2, 32}, Voxel{180, 180, 180, 255});
    addBox(world, {10, 2, 12}, {14, 8, 16}, Voxel{200, 60, 40, 255});
    addBox(world, {18, 2, 20}, {26, 5, 22}, Voxel{60, 90, 200, 255});
    const Camera camera = Camera::create({16.25, 9.5, 1.5}, 0, -20, 60, 96, 64).value();
    ShadeOptions options;
    options.sunDirection = {0.0f, 1.0f, 0.0f};
    options.maxReflections = 1;
    auto gpu = VoxelGpuRenderer::create(*context, world);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    auto image = gpu->render(camera, options);
    ASSERT_TRUE(image.ok()) << image.error().message();
    const Parity p = compareDisplay(*image, render(world, camera, options));
    printParity("axis-aligned boxes", p);
    EXPECT_LE(p.maxAbs, 1);
    EXPECT_EQ(p.differingPixels, 0.0);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// Terrain, reflections, shadows, procedural and PNG-style textures with cutouts, both modes.
TEST(VoxelGpu, TexturedTerrainMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = texturedTerrain();
    const TextureSet textures = testTextures();
    const Camera camera = Camera::lookAt({48, 44, -10}, {48, 20, 50}, 60, 160, 96).value();
    auto gpu = VoxelGpuRenderer::create(*context, world, &textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    for (auto mode : {ShadeOptions::ReflectionMode::RunningAverage,
                      ShadeOptions::ReflectionMode::EnergyConserving}) {
        const ShadeOptions options = terrainShading(mode);
        auto image = gpu->render(camera, options);
        ASSERT_TRUE(image.ok()) << image.error().message();
        const Parity p = compareDisplay(*image, render(world, camera, options, &textures));
        printParity(mode == ShadeOptions::ReflectionMode::EnergyConserving ? "terrain, energy"
                                                                           : "terrain, seed",
                    p);
        EXPECT_LT(p.differingPixels, 0.005);
        EXPECT_LT(p.meanAbs, 0.05);
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// The Preetham clear sky (sky_model.h) on both backends: seen above the terrain, in its mirror
// reflections and, with physical lighting, as the faces' ambient light; a low sun brightens the
// sky around it.
TEST(VoxelGpu, PreethamSkyMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = texturedTerrain();
    const TextureSet textures = testTextures();
    const Camera camera = Camera::lookAt({48, 44, -10}, {48, 40, 50}, 70, 160, 96).value();
    auto gpu = VoxelGpuRenderer::create(*context, world, &textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    for (auto lighting : {ShadeOptions::Lighting::Classic, ShadeOptions::Lighting::Physical}) {
        ShadeOptions options = terrainShading(ShadeOptions::ReflectionMode::EnergyConserving);
        options.lighting = lighting;
        options.skyModel = ShadeOptions::SkyModel::Preetham;
        options.skyTurbidity = 4.0f;
        options.skyZenithLuminance = 0.6f;
        options.sunDirection = {0.3f, 0.25f, 1.0f};
        auto image = gpu->render(camera, options);
        ASSERT_TRUE(image.ok()) << image.error().message();
        const Image cpu = render(world, camera, options, &textures);
        const Parity p = compareDisplay(*image, cpu);
        printParity(lighting == ShadeOptions::Lighting::Physical ? "Preetham sky, physical"
                                                                 : "Preetham sky, classic",
                    p);
        EXPECT_LT(p.differingPixels, 0.005);
        EXPECT_LT(p.meanAbs, 0.05);
        // The sky is the model's, not the gradient's: the top row differs from the default sky.
        ShadeOptions gradient = options;
        gradient.skyModel = ShadeOptions::SkyModel::Gradient;
        const Parity other = compareDisplay(cpu, render(world, camera, gradient, &textures));
        EXPECT_GT(other.differingPixels, 0.2);
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// The shipped garden: PNG textures, cutout leaves, per-texture reflectivity.
TEST(VoxelGpu, GardenSceneMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/garden.json", 192, 108);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto gpu = VoxelGpuRenderer::create(*context, scene->world, &scene->textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    auto image = gpu->render(scene->camera, scene->shading);
    ASSERT_TRUE(image.ok()) << image.error().message();
    const Parity p = compareDisplay(
        *image, render(scene->world, scene->camera, scene->shading, &scene->textures));
    printParity("garden", p);
    EXPECT_LT(p.differingPixels, 0.005);
    EXPECT_LT(p.meanAbs, 0.05);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// Physical lighting: the textured terrain with a metal sphere, a glass block with absorption
// (refraction, total internal reflection), a lamp, every specular and Fresnel model.
TEST(VoxelGpu, PhysicalLightingMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    VoxelWorld world = texturedTerrain();
    addSphere(world, {48, 30, 50}, 7, Voxel{230, 230, 240, alphaForSlot(2)});
    addBox(world, {56, 18, 30}, {66, 28, 40}, Voxel{255, 255, 255, alphaForSlot(3)});
    addBox(world, {30, 22, 34}, {34, 26, 38}, Voxel{255, 255, 255, alphaForSlot(4)});
    const TextureSet textures = testTextures();
    ShadeOptions o = terrainShading(ShadeOptions::ReflectionMode::EnergyConserving);
    o.lighting = ShadeOptions::Lighting::Physical;
    o.maxReflections = 6;
    // The lamp lights the terrain too (emitter_light_gpu_test.cpp has its own parity tests): its
    // shadow rays from faces under the glass block start inside the medium on both backends.
    Material metal;
    metal.name = "metal";
    metal.metallic = 1.0f;
    metal.roughness = 0.05f;
    Material glass;
    glass.name = "glass";
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    glass.absorption = {0.05f, 0.02f, 0.1f};
    glass.proceduralTexture = true;
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = {4.0f, 3.0f, 1.0f};
    ASSERT_TRUE(o.materials.setSlot(2, metal).ok());
    ASSERT_TRUE(o.materials.setSlot(3, glass).ok());
    ASSERT_TRUE(o.materials.setSlot(4, lamp).ok());
    Material leafy = defaultMaterial();
    leafy.name = "leafy";
    leafy.roughness = 0.2f;  // half mirror, half sky
    leafy.proceduralTexture = false;
    ASSERT_TRUE(o.materials.setSlot(0, leafy).ok());
    const Camera camera = Camera::lookAt({48, 44, -10}, {48, 20, 50}, 60, 160, 96).value();
    auto gpu = VoxelGpuRenderer::create(*context, world, &textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    for (auto specular : {ShadeOptions::Specular::Ggx, ShadeOptions::Specular::BlinnPhong,
                          ShadeOptions::Specular::None}) {
        o.specular = specular;
        o.fresnel = specular == ShadeOptions::Specular::BlinnPhong
                        ? ShadeOptions::FresnelModel::Schlick
                        : ShadeOptions::FresnelModel::Exact;
        auto image = gpu->render(camera, o);
        ASSERT_TRUE(image.ok()) << image.error().message();
        const Image cpu = render(world, camera, o, &textures);
        const Parity p = compareDisplay(*image, cpu);
        printParity("physical terrain", p);
        EXPECT_LT(p.differingPixels, 0.01);
        EXPECT_LT(p.meanAbs, 0.1);
    }
    // The GPU did light physically: far from its classic image.
    ShadeOptions classic = o;
    classic.lighting = ShadeOptions::Lighting::Classic;
    auto physicalImage = gpu->render(camera, o);
    auto classicImage = gpu->render(camera, classic);
    ASSERT_TRUE(physicalImage.ok() && classicImage.ok());
    EXPECT_GT(compareDisplay(*physicalImage, *classicImage).differingPixels, 0.5);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// The shipped glass scene: refraction through clear and absorbing blocks, a mirror wall, a lamp.
TEST(VoxelGpu, GlassSceneMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/glass.json", 160, 90);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto gpu = VoxelGpuRenderer::create(*context, scene->world, &scene->textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    auto image = gpu->render(scene->camera, scene->shading);
    ASSERT_TRUE(image.ok()) << image.error().message();
    const Parity p = compareDisplay(
        *image, render(scene->world, scene->camera, scene->shading, &scene->textures));
    printParity("glass", p);
    EXPECT_LT(p.differingPixels, 0.01);
    EXPECT_LT(p.meanAbs, 0.1);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(VoxelGpu, UpdateRegionMatchesACpuRenderOfTheEditedWorld) {
    LUXEL_REQUIRE_GPU(context);
    VoxelWorld world = texturedTerrain();
    const TextureSet textures = testTextures();
    const Camera camera = Camera::lookAt({48, 44, -10}, {48, 20, 50}, 60, 128, 80).value();
    const ShadeOptions options = terrainShading(ShadeOptions::ReflectionMode::EnergyConserving);
    auto gpu = VoxelGpuRenderer::create(*context, world, &textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    const Image before = gpu->render(camera, options).value();
    // Carve the sphere out, put a block in the sky (a chunk that was empty before).
    addSphere(world, {48, 30, 50}, 7.5f, Voxel{});
    addBox(world, {40, 36, 30}, {50, 44, 36}, Voxel{250, 200, 40, 255});
    ASSERT_TRUE(gpu->updateRegion(world, {40, 22, 30}, {57, 44, 58}).ok());
    auto after = gpu->render(camera, options);
    ASSERT_TRUE(after.ok()) << after.error().message();
    const Parity p = compareDisplay(*after, render(world, camera, options, &textures));
    printParity("after updateRegion", p);
    EXPECT_LT(p.differingPixels, 0.005);
    EXPECT_GT(compareDisplay(before, *after).differingPixels, 0.01);  // the edit shows
    // A region outside the world uploads nothing and is fine.
    EXPECT_TRUE(gpu->updateRegion(world, {-10, -10, -10}, {-1, -1, -1}).ok());
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(VoxelGpu, CallbackReflectivityIsRefused) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = VoxelWorld::create({8, 8, 8}, 8).value();
    auto gpu = VoxelGpuRenderer::create(*context, world);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ShadeOptions options;
    options.materialReflectivity = [](const Voxel&) { return 0.5f; };
    const Camera camera = Camera::create({4, 4, -4}, 0, 0, 60, 8, 8).value();
    auto image = gpu->render(camera, options);
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.error().message().find("per texture"), std::string::npos);
}

}  // namespace
}  // namespace luxel::voxel
