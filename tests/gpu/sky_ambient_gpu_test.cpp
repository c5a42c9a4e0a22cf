// Sky ambient with occlusion on the GPU (voxel/sky_ambient.glsl) against the CPU (render() in
// render_image.h) on the shipped thin-walls (a sealed room beside full sun) and garden (cutout
// leaves the rays pass through), with several samples per pixel so each sample's stream is
// checked too. Both draw the same numbers and directions (shared/path_rng.h, shared/
// sky_ambient.h); the rays walk in float on the GPU and in double on the CPU, so a ray grazing an
// edge may land on the other side at a few pixels: the physical tests' 1% bound.
#include <gtest/gtest.h>

#include <string>

#include "luxel/gpu/context.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"
#include "support/display_parity.h"
#include "support/gpu_test_context.h"

namespace luxel::voxel {
namespace {

using test::compareDisplay;
using test::Parity;
using test::printParity;

TEST(SkyAmbientGpu, MatchesTheCpuOnShippedScenes) {
    LUXEL_REQUIRE_GPU(context);
    struct Case {
        const char* name;
        int rays, samples;
    };
    for (const Case& c : {Case{"thin-walls.json", 8, 1}, Case{"garden.json", 4, 2}}) {
        auto loaded =
            loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/" + c.name, 64, 36);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message();
        VoxelScene& scene = *loaded;
        scene.shading.lighting = ShadeOptions::Lighting::Physical;
        scene.shading.skyAmbientRays = c.rays;
        scene.shading.samplesPerPixel = c.samples;
        auto gpu = VoxelGpuRenderer::create(*context, scene.world, &scene.textures);
        ASSERT_TRUE(gpu.ok()) << gpu.error().message();
        auto traced = gpu->render(scene.camera, scene.shading);
        ASSERT_TRUE(traced.ok()) << traced.error().message();
        const Parity p = compareDisplay(
            *traced, render(scene.world, scene.camera, scene.shading, &scene.textures));
        printParity(std::string(c.name) + ", sky ambient rays", p);
        EXPECT_LT(p.differingPixels, 0.01) << c.name;
        EXPECT_LT(p.meanAbs, 0.1) << c.name;
        // The rays reached the GPU image: it is not the constant share's.
        ShadeOptions constant = scene.shading;
        constant.skyAmbientRays = 0;
        auto shared = gpu->render(scene.camera, constant);
        ASSERT_TRUE(shared.ok()) << shared.error().message();
        EXPECT_GT(compareDisplay(*traced, *shared).differingPixels, 0.2) << c.name;
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::voxel
