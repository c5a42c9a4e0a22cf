// Octree rendering (octree_render.h): the GPU pass against its CPU twin in every mode, and what
// each mode must show.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "luxel/core/metrics.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_gpu.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/volume_generators.h"
#include "support/gpu_test_context.h"

namespace luxel::octree {
namespace {

TEST(OctreeRender, GpuPassMatchesTheCpuTwinInEveryMode) {
    if (!test::sharedGpuContext())
        GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    const Octree tree = *buildOctree(*makePhantom(48));
    const voxel::Camera camera = *voxel::Camera::lookAt({90, 60, -50}, {24, 24, 24}, 40, 64, 48);
    auto uploaded = OctreeGpu::create(*test::sharedGpuContext(), tree);
    ASSERT_TRUE(uploaded.ok()) << uploaded.error().message();
    struct Case {
        OctreeMode mode;
        float opacityScale;
        float sunRadius;
        double bound;  // float vs double: chords and ties differ slightly
        std::uint8_t windowLow = 0, windowHigh = 255;
    };
    for (const Case& c :
         {Case{OctreeMode::Surface, 1.0f, 0.0f, 2e-3}, Case{OctreeMode::Surface, 0.3f, 4.0f, 5e-3},
          Case{OctreeMode::Volume, 0.4f, 0.0f, 1e-2},
          Case{OctreeMode::Volume, 0.8f, 0.0f, 1e-2, 100, 240},
          Case{OctreeMode::Additive, 0.05f, 0.0f, 2e-3}}) {
        OctreeRenderOptions o;
        o.mode = c.mode;
        o.opacityScale = c.opacityScale;
        o.sunRadiusDegrees = c.sunRadius;
        o.shadowSamples = c.sunRadius > 0 ? 8 : 1;
        o.threshold = 100;
        o.windowLow = c.windowLow;
        o.windowHigh = c.windowHigh;
        auto cpu = renderOctree(tree, camera, o);
        auto gpu = uploaded->render(camera, o);
        ASSERT_TRUE(cpu.ok() && gpu.ok());
        EXPECT_LT(compareImages(*gpu, *cpu)->relativeL1, c.bound) << octreeModeName(c.mode);
    }
    EXPECT_EQ(test::sharedGpuContext()->validationMessages(), 0)
        << test::sharedGpuContext()->lastValidationMessage();
}

// A 16^3 grey cube in a 32^3 tree, seen along +z from the front.
struct CubeScene {
    Octree tree = [] {
        Volume v = *Volume::create({32, 32, 32});
        for (int z = 8; z < 24; ++z)
            for (int y = 8; y < 24; ++y)
                for (int x = 8; x < 24; ++x) v.set(x, y, z, 128);
        return *buildOctree(v);
    }();
    voxel::Camera camera = *voxel::Camera::lookAt({16, 16, -40}, {16, 16, 16}, 30, 33, 33);
};

TEST(OctreeRender, VolumeModeFollowsBeerLambertThroughTheCube) {
    CubeScene s;
    OctreeRenderOptions o;
    o.mode = OctreeMode::Volume;
    o.scattering = false;
    o.sky = {1, 1, 1};
    o.ambient = 0;
    o.opacityScale = 0.25f;  // a = 128 / 255 * 0.25 per voxel
    const Image image = *renderOctree(s.tree, s.camera, o);
    // The centre ray crosses 16 voxels: the sky behind shows through T = (1 - a)^16 and the
    // medium, without scattering, emits its colour (light grey, 0.8 in sRGB) over 1 - T.
    const double a = 128.0 / 255.0 * 0.25;
    const double t = std::pow(1 - a, 16.0);
    const double grey = std::pow((0.8 + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(image.at(16, 16, 0), grey * (1 - t) + t, 1e-4);
    EXPECT_NEAR(image.at(0, 0, 0), 1.0, 1e-6);  // a corner ray misses the cube
}

// The opacity window: below its low end a value is clear, above its high end full strength, and
// linear between, so the cube of 128 reads (128 - 64) / (192 - 64) = 0.5 of the scale; with the
// window above 128 the cube vanishes and the sky shows through untouched.
TEST(OctreeRender, OpacityWindowMapsValuesLinearlyBetweenItsEnds) {
    CubeScene s;
    OctreeRenderOptions o;
    o.mode = OctreeMode::Volume;
    o.scattering = false;
    o.sky = {1, 1, 1};
    o.ambient = 0;
    o.opacityScale = 0.25f;
    o.windowLow = 64;
    o.windowHigh = 192;
    const Image image = *renderOctree(s.tree, s.camera, o);
    const double a = 0.5 * 0.25;
    const double t = std::pow(1 - a, 16.0);
    const double grey = std::pow((0.8 + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(image.at(16, 16, 0), grey * (1 - t) + t, 1e-4);
    o.windowLow = 128;
    const Image clear = *renderOctree(s.tree, s.camera, o);
    EXPECT_NEAR(clear.at(16, 16, 0), 1.0, 1e-6);
    o.windowHigh = 100;  // not above the low end
    auto bad = renderOctree(s.tree, s.camera, o);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("opacity window"), std::string::npos);
}

TEST(OctreeRender, SurfaceShadowsDarkenTheGroundBehindABlock) {
    Volume v = *Volume::create({32, 32, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) v.set(x, 0, z, 255);  // ground
    for (int y = 1; y < 12; ++y)
        for (int z = 14; z < 18; ++z)
            for (int x = 14; x < 18; ++x) v.set(x, y, z, 255);  // a pillar
    const Octree tree = *buildOctree(v);
    const voxel::Camera camera = *voxel::Camera::lookAt({16, 60, 15.9}, {16, 0, 16}, 60, 64, 64);
    OctreeRenderOptions o;
    o.sunDirection = {1, 1, 0};  // the shadow falls toward -x
    const Image lit = *renderOctree(tree, camera, o);
    o.shadows = false;
    const Image unshadowed = *renderOctree(tree, camera, o);
    // Ground pixels on the -x side of the pillar, in its shadow, are darker than without shadows;
    // those on the +x side are the same.
    int darker = 0, same = 0;
    for (int y = 28; y < 36; ++y) {
        for (int x = 2; x < 62; ++x) {
            if (lit.at(x, y, 0) < unshadowed.at(x, y, 0) * 0.9f) ++darker;
            if (lit.at(x, y, 0) == unshadowed.at(x, y, 0)) ++same;
        }
    }
    EXPECT_GE(darker, 30);  // the shadow: 11 voxels long, 4 wide, about a voxel per pixel
    EXPECT_GT(same, 200);
    o.shadows = true;
    o.sunRadiusDegrees = 8;
    o.shadowSamples = 16;
    const Image soft = *renderOctree(tree, camera, o);
    int penumbra = 0;  // soft shadows: pixels between lit and fully shadowed
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float f = soft.at(x, y, 0) / unshadowed.at(x, y, 0);
            penumbra += f > 0.3f && f < 0.95f ? 1 : 0;
        }
    EXPECT_GT(penumbra, 20);
}

TEST(OctreeRender, BadOptionsAreNamed) {
    CubeScene s;
    OctreeRenderOptions o;
    o.albedo = std::nanf("");
    auto r = renderOctree(s.tree, s.camera, o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message().find("albedo"), std::string::npos);
    EXPECT_FALSE(parseOctreeMode("xray").ok());
    EXPECT_EQ(*parseOctreeMode("additive"), OctreeMode::Additive);
}

}  // namespace
}  // namespace luxel::octree
