// Filtered textures and anti-aliasing on the GPU (texture_sample.glsl, the sample loop in
// voxel_render.comp.glsl) against the CPU (TextureSet::sample, render_image.cpp): whole images
// with every filter and several samples per pixel. The GPU traces in float, the CPU in double,
// so a few pixels may see another voxel or texel; the bounds say how few.
#include <gtest/gtest.h>

#include <cstdio>

#include "luxel/voxel/generators.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"
#include "support/display_parity.h"
#include "support/gpu_test_context.h"

namespace luxel::voxel {
namespace {

// Pixels agree when no display channel is off by more than 2/255: the GPU traces in float.
test::Parity compare(const Image& a, const Image& b) {
    return test::compareDisplay(a, b, 2);
}

// A fine checkerboard lawn under a grazing camera (antialias_test.cpp's view).
struct Lawn {
    VoxelWorld world;
    TextureSet textures;
};

Lawn lawn() {
    VoxelWorld world = VoxelWorld::create({96, 8, 96}, 8).value();
    TextureSet textures;
    Texture t{"checker", 16, 16, {}, std::nullopt};
    for (int i = 0; i < 256; ++i) {
        const float x = ((i % 16) + (i / 16)) % 2 ? 0.9f : 0.1f;
        t.texels.push_back({x, 0.5f * x, 0.3f, 1});
    }
    const int slot = textures.add(std::move(t)).value();
    addBox(world, {0, 0, 0}, {96, 1, 96}, Voxel{255, 255, 255, alphaForSlot(slot)});
    return {std::move(world), std::move(textures)};
}

TEST(TextureGpu, FilteredLawnMatchesTheCpu) {
    gpu::Context* context = test::sharedGpuContext();
    if (!context) GTEST_SKIP() << "no Vulkan device";
    const Lawn l = lawn();
    const Camera camera = Camera::lookAt({48.3, 2.6, 1.7}, {47.1, 0.8, 30.0}, 50, 64, 40).value();
    auto gpu = VoxelGpuRenderer::create(*context, l.world, &l.textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    // The filters do change the image (so agreement is not agreement on nearest texels).
    ShadeOptions nearest, aniso;
    aniso.textureFilter = TextureFilter::Anisotropic;
    EXPECT_GT(compare(gpu->render(camera, nearest).value(), gpu->render(camera, aniso).value())
                  .differingPixels,
              0.2);
    for (TextureFilter filter :
         {TextureFilter::Nearest, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
        for (int samples : {1, 4, 6}) {
            ShadeOptions o;
            o.maxReflections = 1;
            o.reflectionMode = ShadeOptions::ReflectionMode::EnergyConserving;
            o.textureFilter = filter;
            o.samplesPerPixel = samples;
            o.maxAnisotropy = 8;
            const Image cpu = render(l.world, camera, o, &l.textures);
            const Image image = gpu->render(camera, o).value();
            const test::Parity d = compare(image, cpu);
            std::printf("lawn %s, %d spp: %.3f%% pixels differ by > 2/255, mean %.4f/255\n",
                        textureFilterName(filter), samples, 100 * d.differingPixels, d.meanAbs);
            EXPECT_LT(d.differingPixels, 0.01) << textureFilterName(filter) << " " << samples;
            EXPECT_LT(d.meanAbs, 0.2) << textureFilterName(filter) << " " << samples;
        }
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// The garden: cutout leaves (decided on the nearest texel on both), bricks with a normal map
// uploaded, reflections whose cones widen at each bounce.
TEST(TextureGpu, FilteredGardenWithSamplesMatchesTheCpu) {
    gpu::Context* context = test::sharedGpuContext();
    if (!context) GTEST_SKIP() << "no Vulkan device";
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/garden.json", 128, 72);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto gpu = VoxelGpuRenderer::create(*context, scene->world, &scene->textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ShadeOptions o = scene->shading;
    o.textureFilter = TextureFilter::Anisotropic;
    o.samplesPerPixel = 4;
    const test::Parity d = compare(gpu->render(scene->camera, o).value(),
                                   render(scene->world, scene->camera, o, &scene->textures));
    std::printf("garden anisotropic, 4 spp: %.3f%% pixels differ by > 2/255, mean %.4f/255\n",
                100 * d.differingPixels, d.meanAbs);
    EXPECT_LT(d.differingPixels, 0.01);
    EXPECT_LT(d.meanAbs, 0.2);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::voxel
