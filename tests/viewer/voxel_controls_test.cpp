// Voxel-mode surface and post keys, and the renderer's upscaling paths (no display needed).
#include <gtest/gtest.h>

#include "luxel/voxel/generators.h"
#include "renderer_voxel.h"
#include "voxel_controls.h"

namespace luxel::viewer {
namespace {

TEST(VoxelControls, KeysToggleAndCycleTheOptions) {
    VoxelState state;
    const voxel::ShadeOptions before = state.shading;
    EXPECT_TRUE(applyVoxelSurfaceKey('p', state));
    EXPECT_NE(state.shading.lighting, before.lighting);
    EXPECT_TRUE(applyVoxelSurfaceKey('v', state));
    EXPECT_NE(state.shading.shadowSettings.method, before.shadowSettings.method);
    for (int i = 0; i < 6; ++i) applyVoxelSurfaceKey('v', state);  // 7 methods: back to the start
    EXPECT_EQ(state.shading.shadowSettings.method, before.shadowSettings.method);
    applyVoxelSurfaceKey('g', state);
    EXPECT_NE(state.shading.specular, before.specular);
    applyVoxelSurfaceKey('y', state);
    EXPECT_NE(state.shading.fresnel, before.fresnel);
    applyVoxelSurfaceKey('r', state);
    EXPECT_NE(state.shading.refraction, before.refraction);
    applyVoxelSurfaceKey('n', state);
    EXPECT_NE(state.shading.normalMaps, before.normalMaps);
    applyVoxelSurfaceKey('x', state);
    EXPECT_NE(state.shading.textureFilter, before.textureFilter);
    applyVoxelSurfaceKey('.', state);
    EXPECT_EQ(state.shading.samplesPerPixel, before.samplesPerPixel * 2);
    applyVoxelSurfaceKey(',', state);
    EXPECT_EQ(state.shading.samplesPerPixel, before.samplesPerPixel);
    applyVoxelSurfaceKey('o', state);
    EXPECT_GT(state.post.bloom.strength, 0.0f);
    EXPECT_FALSE(applyVoxelSurfaceKey('z', state));
}

TEST(VoxelControls, UCyclesThroughTheUpscalers) {
    VoxelState state;
    EXPECT_EQ(upscalingLabel(state), "native");
    const char* expected[] = {"bilinear 0.50", "edge 0.50", "temporal 0.50", "native"};
    for (const char* label : expected) {
        applyVoxelSurfaceKey('u', state);
        EXPECT_EQ(upscalingLabel(state), label);
    }
}

TEST(VoxelControls, RendererUpscalesAndAccumulates) {
    auto world = voxel::VoxelWorld::create({16, 8, 16}, 8);
    ASSERT_TRUE(world.ok());
    voxel::addBox(*world, {0, 0, 0}, {16, 2, 16}, {90, 160, 70, 255});
    voxel::addBox(*world, {6, 2, 6}, {10, 6, 10}, {200, 120, 90, 255});
    RendererVoxel renderer(std::move(*world), makeCpuVoxelFrameSource());
    VoxelState state;
    state.camera.position = {8, 6, -10};
    state.width = 48;
    state.height = 32;
    state.post.internalScale = 0.5f;
    state.post.upscaler = post::Upscaler::Edge;
    state.post.bloom.strength = 0.2f;
    VoxelState copy = state;
    renderer.setState(std::move(copy));
    Frame frame = renderer.step();
    ASSERT_TRUE(frame.note.empty()) << frame.note;
    EXPECT_EQ(frame.picture.width(), 48);
    EXPECT_EQ(frame.picture.height(), 32);
    EXPECT_FALSE(renderer.hasMoreWork());
    state.temporal = true;
    copy = state;
    renderer.setState(std::move(copy));
    int frames = 0;
    while (renderer.hasMoreWork() && frames < 100) {
        frame = renderer.step();
        ASSERT_TRUE(frame.note.empty()) << frame.note;
        ++frames;
    }
    EXPECT_EQ(frames, 32);  // a still view keeps accumulating, then rests
    EXPECT_EQ(frame.picture.width(), 48);
}

}  // namespace
}  // namespace luxel::viewer
