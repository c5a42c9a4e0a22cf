// The ray caster's light from emissive voxels on the GPU against the CPU (render() in
// render_image.h): the shipped thin-walls (a dim lamp behind a partition), glass (a lamp beside
// glass, shadow rays through it) and cottage (many glowing voxels). Both take the same lists
// (EmitterLights) and the same float arithmetic at a point; the shadow rays walk in float on the
// GPU and in double on the CPU, so a ray grazing a voxel edge may land on the other side at a few
// pixels: the bound on differing pixels is the physical tests' 1%.
#include <gtest/gtest.h>

#include <string>

#include "luxel/gpu/context.h"
#include "luxel/voxel/emitter_light.h"
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

VoxelScene shipped(const std::string& name) {
    auto scene = loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/" + name, 128, 72);
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    return std::move(*scene);
}

TEST(EmitterLightGpu, MatchesTheCpuOnShippedScenes) {
    LUXEL_REQUIRE_GPU(context);
    for (const char* name : {"thin-walls.json", "glass.json", "cottage.json"}) {
        VoxelScene scene = shipped(name);
        ASSERT_EQ(scene.shading.lighting, ShadeOptions::Lighting::Physical) << name;
        ASSERT_FALSE(EmitterLights::build(scene.world, scene.shading.materials).empty()) << name;
        auto gpu = VoxelGpuRenderer::create(*context, scene.world, &scene.textures);
        ASSERT_TRUE(gpu.ok()) << gpu.error().message();
        auto lit = gpu->render(scene.camera, scene.shading);
        ASSERT_TRUE(lit.ok()) << lit.error().message();
        const Parity p =
            compareDisplay(*lit, render(scene.world, scene.camera, scene.shading, &scene.textures));
        printParity(std::string(name) + ", emitter light", p);
        EXPECT_LT(p.differingPixels, 0.01) << name;
        EXPECT_LT(p.meanAbs, 0.1) << name;
        // The light reached the GPU image, and switching it off there restores the CPU's old one.
        ShadeOptions off = scene.shading;
        off.emitterLight = false;
        auto dark = gpu->render(scene.camera, off);
        ASSERT_TRUE(dark.ok()) << dark.error().message();
        EXPECT_GT(compareDisplay(*lit, *dark).differingPixels, 0.01) << name;
        const Parity q =
            compareDisplay(*dark, render(scene.world, scene.camera, off, &scene.textures));
        printParity(std::string(name) + ", off", q);
        EXPECT_LT(q.differingPixels, 0.01) << name;
        // More shadow rays per face: the same lists, still the CPU's picture.
        ShadeOptions many = scene.shading;
        many.emitterRays = 9;
        auto nine = gpu->render(scene.camera, many);
        ASSERT_TRUE(nine.ok()) << nine.error().message();
        const Parity r =
            compareDisplay(*nine, render(scene.world, scene.camera, many, &scene.textures));
        printParity(std::string(name) + ", 9 rays", r);
        EXPECT_LT(r.differingPixels, 0.01) << name;
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// A room lit by a 14 x 10 lamp panel in its ceiling (merged into rectangles of up to 4 x 4
// faces, more than the 16 emitters a point keeps before merging) over a pillar that casts a soft
// shadow: the rectangles' light, their clipping at the walls under the panel's plane and the
// shadow rays aimed over each rectangle, the same on both backends.
TEST(EmitterLightGpu, MatchesTheCpuUnderALampPanel) {
    LUXEL_REQUIRE_GPU(context);
    auto scene = parseVoxelScene(R"({
        "type": "voxel",
        "materials": [{"name": "lamp", "emission": [2.0, 1.8, 1.5]}],
        "world": {"source": "empty", "size": [32, 12, 32], "chunk": 8, "shapes": [
            {"type": "box", "min": [0, 0, 0], "max": [32, 1, 32], "color": [180, 180, 180]},
            {"type": "box", "min": [4, 1, 4], "max": [5, 10, 28], "color": [200, 190, 170]},
            {"type": "box", "min": [27, 1, 4], "max": [28, 10, 28], "color": [200, 190, 170]},
            {"type": "box", "min": [4, 1, 27], "max": [28, 10, 28], "color": [200, 190, 170]},
            {"type": "box", "min": [4, 10, 4], "max": [28, 11, 28], "color": [200, 190, 170]},
            {"type": "box", "min": [9, 9, 12], "max": [23, 10, 22], "material": "lamp"},
            {"type": "box", "min": [14, 1, 15], "max": [17, 5, 18], "color": [120, 60, 50]}]},
        "camera": {"position": [16, 6, 2], "look_at": [16, 2, 20], "fov": 75, "size": [128, 72]},
        "sky": {"top": [0, 0, 0], "horizon": [0, 0, 0]},
        "render": {"lighting": "physical", "shadows": true, "textures": false,
                   "sky_ambient": 0}})",
                                 "panel.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const EmitterLights lights = EmitterLights::build(scene->world, scene->shading.materials);
    EXPECT_EQ(lights.faceCount(), 14 * 10 + 2 * 14 + 2 * 10);  // its top touches the ceiling
    // Below, 4 x 3 rectangles (sides of 4, 4, 4, 2 along x and 4, 4, 2 along z); the sides in runs
    // of up to 4: 3 on each x side, 4 on each z side.
    EXPECT_EQ(lights.emitterCount(), 12 + 2 * 3 + 2 * 4);
    auto gpu = VoxelGpuRenderer::create(*context, scene->world, &scene->textures);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    for (const int rays : {4, 9}) {
        ShadeOptions o = scene->shading;
        o.emitterRays = rays;
        auto image = gpu->render(scene->camera, o);
        ASSERT_TRUE(image.ok()) << image.error().message();
        const Parity p =
            compareDisplay(*image, render(scene->world, scene->camera, o, &scene->textures));
        printParity("lamp panel, " + std::to_string(rays) + " rays", p);
        EXPECT_LT(p.differingPixels, 0.01);
        EXPECT_LT(p.meanAbs, 0.1);
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::voxel
