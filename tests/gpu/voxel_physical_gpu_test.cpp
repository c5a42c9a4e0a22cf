// Physical lighting on the GPU against the CPU (render() in render_image.h) on the shipped garden:
// sun visibility by the map and field methods (the render pass reads the arrays the CPU built,
// sun_visibility.glsl), filtered textures and the bricks' normal map over ray-cone footprints.
// The GPU runs in float: the SDF march and the moment lookups can land on the other side of a
// shadow edge at a few pixels, so the bound on differing pixels is the physical tests' 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "gpu/shaders/shared/shadow_layout.h"
#include "luxel/core/tonemap.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"
#include "support/display_parity.h"
#include "support/gpu_test_context.h"

namespace luxel::voxel {
namespace {

using test::compareDisplay;
using test::Parity;
using test::printParity;

VoxelScene garden() {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/garden.json", 128, 72);
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    VoxelScene s = std::move(*scene);
    s.shading.lighting = ShadeOptions::Lighting::Physical;
    s.shading.shadows = true;
    s.shading.sunAngularRadius = 0.05;  // wide penumbrae: the soft methods differ from hard
    s.shading.shadowSettings.mapSize = 256;
    s.shading.shadowSettings.blendNear = 14;  // the band crosses the lawn
    s.shading.shadowSettings.blendFar = 30;
    return s;
}

TEST(VoxelPhysicalGpu, SunVisibilityMethodsMatchTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    VoxelScene scene = garden();
    auto gpu = VoxelGpuRenderer::create(*context, scene.world, &scene.textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ShadeOptions hard = scene.shading;
    hard.shadowSettings.method = ShadowMethod::Hard;
    auto hardImage = gpu->render(scene.camera, hard);
    ASSERT_TRUE(hardImage.ok()) << hardImage.error().message();
    for (ShadowMethod method : {ShadowMethod::Msm, ShadowMethod::Vsm, ShadowMethod::Sdf,
                                ShadowMethod::Blend, ShadowMethod::FloodFill}) {
        ShadeOptions o = scene.shading;
        o.shadowSettings.method = method;
        auto image = gpu->render(scene.camera, o);
        ASSERT_TRUE(image.ok()) << image.error().message();
        const Parity p =
            compareDisplay(*image, render(scene.world, scene.camera, o, &scene.textures));
        printParity(std::string("garden, ") + shadowMethodName(method), p);
        EXPECT_LT(p.differingPixels, 0.01) << shadowMethodName(method);
        EXPECT_LT(p.meanAbs, 0.1) << shadowMethodName(method);
        // The method's arrays were read: the image is not the hard-shadowed one.
        EXPECT_GT(compareDisplay(*image, *hardImage).differingPixels, 0.01)
            << shadowMethodName(method);
    }
    // Hard stays the pass's own shadow ray, as the CPU's.
    const Parity p =
        compareDisplay(*hardImage, render(scene.world, scene.camera, hard, &scene.textures));
    printParity("garden, hard", p);
    EXPECT_LT(p.differingPixels, 0.01);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(VoxelPhysicalGpu, FilteredTexturesAndNormalMapsMatchTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    VoxelScene scene = garden();
    scene.shading.shadowSettings.method = ShadowMethod::Hard;
    scene.shading.sunDirection = {-0.6f, 0.9f, -0.5f};  // onto the brick walls facing the camera
    // Close to the bricks' corner, the lawn receding: texels both magnified and minified (at a
    // distance the filtered normal map averages to the flat face).
    scene.camera = Camera::lookAt({27, 6, 23}, {37, 4, 34}, 60, 128, 72).value();
    auto gpu = VoxelGpuRenderer::create(*context, scene.world, &scene.textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    struct Case {
        const char* name;
        TextureFilter filter;
        int samples;
        bool normalMaps;
    };
    for (const Case& c : {Case{"anisotropic, normal maps", TextureFilter::Anisotropic, 1, true},
                          Case{"trilinear, normal maps, 4 spp", TextureFilter::Trilinear, 4, true},
                          Case{"nearest, normal maps", TextureFilter::Nearest, 1, true},
                          Case{"anisotropic, flat", TextureFilter::Anisotropic, 1, false}}) {
        ShadeOptions o = scene.shading;
        o.textureFilter = c.filter;
        o.maxAnisotropy = 8;
        o.samplesPerPixel = c.samples;
        o.normalMaps = c.normalMaps;
        auto image = gpu->render(scene.camera, o);
        ASSERT_TRUE(image.ok()) << image.error().message();
        const Parity p =
            compareDisplay(*image, render(scene.world, scene.camera, o, &scene.textures));
        printParity(std::string("garden, ") + c.name, p);
        EXPECT_LT(p.differingPixels, 0.01) << c.name;
        EXPECT_LT(p.meanAbs, 0.1) << c.name;
    }
    // The normal map and the filter reach the GPU image.
    ShadeOptions bumped = scene.shading, flat = scene.shading, nearest = scene.shading;
    bumped.textureFilter = flat.textureFilter = TextureFilter::Anisotropic;
    bumped.normalMaps = true;
    flat.normalMaps = false;
    nearest.textureFilter = TextureFilter::Nearest;
    nearest.normalMaps = true;
    const Image b = gpu->render(scene.camera, bumped).value();
    EXPECT_GT(compareDisplay(b, gpu->render(scene.camera, flat).value()).differingPixels, 0.02);
    EXPECT_GT(compareDisplay(b, gpu->render(scene.camera, nearest).value()).differingPixels, 0.02);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(VoxelPhysicalGpu, GivenVisibilityEqualsTheBuiltOneAndEditsRebuild) {
    LUXEL_REQUIRE_GPU(context);
    VoxelScene scene = garden();
    scene.shading.shadowSettings.method = ShadowMethod::Sdf;
    auto gpu = VoxelGpuRenderer::create(*context, scene.world, &scene.textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    const Image built = gpu->render(scene.camera, scene.shading).value();
    const ShadeOptions& s = scene.shading;
    auto visibility = SunVisibility::build(
        scene.world, &scene.textures,
        {{s.sunDirection.x, s.sunDirection.y, s.sunDirection.z}, s.sunAngularRadius},
        s.shadowSettings);
    ASSERT_TRUE(visibility.ok()) << visibility.error().message();
    ShadeOptions given = scene.shading;
    given.sunVisibility = &*visibility;
    const Image fromGiven = gpu->render(scene.camera, given).value();
    EXPECT_EQ(compareDisplay(built, fromGiven).meanAbs, 0.0);
    // An edit: a wall across the lawn. The next render rebuilds the field.
    for (int z = 8; z < 32; ++z) {
        for (int y = 1; y < 12; ++y) scene.world.set(20, y, z, Voxel{200, 60, 60, 255});
    }
    ASSERT_TRUE(gpu->updateRegion(scene.world, {20, 1, 8}, {21, 12, 32}).ok());
    auto after = gpu->render(scene.camera, scene.shading);
    ASSERT_TRUE(after.ok()) << after.error().message();
    const Parity p =
        compareDisplay(*after, render(scene.world, scene.camera, scene.shading, &scene.textures));
    printParity("garden, sdf after an edit", p);
    EXPECT_LT(p.differingPixels, 0.01);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(VoxelPhysicalGpu, ShadowArraysAreCountedAndBudgeted) {
    LUXEL_REQUIRE_GPU(context);
    VoxelScene scene = garden();
    scene.shading.shadowSettings.method = ShadowMethod::Msm;
    auto gpu = VoxelGpuRenderer::create(*context, scene.world, &scene.textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ShadeOptions off = scene.shading;
    off.shadows = false;
    ASSERT_TRUE(gpu->render(scene.camera, off).ok());
    const std::uint64_t before = gpu->deviceBytes();
    ASSERT_TRUE(gpu->render(scene.camera, scene.shading).ok());
    // The placeholders (ShadowParams and three words) are replaced by the method's arrays.
    const std::uint64_t placeholders = sizeof(gpu::shared::ShadowParams) + 12;
    EXPECT_EQ(gpu->deviceBytes() - before + placeholders,
              estimateVoxelShadowGpuMemory(scene.world.size(), scene.shading.shadowSettings));
    EXPECT_GT(gpu->deviceBytes() - before, 256u * 256u * 16u - placeholders);

    // The distance field's arrays: distances and nearest-cube features, counted alike.
    ShadeOptions sdf = scene.shading;
    sdf.shadowSettings.method = ShadowMethod::Sdf;
    ASSERT_TRUE(gpu->render(scene.camera, sdf).ok());
    EXPECT_EQ(gpu->deviceBytes() - before + placeholders,
              estimateVoxelShadowGpuMemory(scene.world.size(), sdf.shadowSettings));

    // Exact has no GPU twin: refused, naming the method.
    ShadeOptions exact = scene.shading;
    exact.shadowSettings.method = ShadowMethod::Exact;
    auto refused = gpu->render(scene.camera, exact);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message().find("'exact'"), std::string::npos)
        << refused.error().message();

    // A budget that fits the world but not a 4096^2 moment map.
    const std::uint64_t world = estimateVoxelGpuMemory(scene.world.size(), scene.world.chunkSize(),
                                                       &scene.textures, 1920, 1080);
    auto tight = VoxelGpuRenderer::create(*context, scene.world, &scene.textures, world);
    ASSERT_TRUE(tight.ok()) << tight.error().message();
    ShadeOptions big = scene.shading;
    big.shadowSettings.mapSize = 4096;
    auto tooBig = tight->render(scene.camera, big);
    ASSERT_FALSE(tooBig.ok());
    EXPECT_NE(tooBig.error().message().find("'msm' needs"), std::string::npos)
        << tooBig.error().message();
}

}  // namespace
}  // namespace luxel::voxel
