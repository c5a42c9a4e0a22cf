// The light cache of volume scattering (octree_light_cache.h): the stride rule, exact corner
// values, reuse across frames, the cached render against the exact per-sample render, and the
// GPU pass against its CPU twin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "luxel/core/metrics.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_gpu.h"
#include "luxel/octree/octree_light_cache.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/volume_generators.h"
#include "support/gpu_test_context.h"

namespace luxel::octree {
namespace {

// The medium and light of scenes/octree/phantom.json before its opacity window (default window).
OctreeRenderOptions phantomOptions() {
    OctreeRenderOptions o;
    o.mode = OctreeMode::Volume;
    o.opacityScale = 0.12f;
    o.albedo = 0.85f;
    o.phaseG = 0.3f;
    o.sunDirection = {0.5f, 0.8f, -0.3f};
    o.sky = {0.02f, 0.02f, 0.03f};
    o.ambient = 1.0f;
    return o;
}

const Octree& phantom256() {
    static const Octree tree = *buildOctree(*makePhantom(256));
    return tree;
}

TEST(OctreeLightCache, AutoStrideIsTheLeastPowerOfTwoWithAtMost128CellsPerAxis) {
    EXPECT_EQ(lightCacheStride({24, 24, 24}, kLightCacheAuto), 1);
    EXPECT_EQ(lightCacheStride({128, 40, 9}, kLightCacheAuto), 1);
    EXPECT_EQ(lightCacheStride({256, 256, 256}, kLightCacheAuto), 2);
    EXPECT_EQ(lightCacheStride({20, 257, 3}, kLightCacheAuto), 4);
    EXPECT_EQ(lightCacheStride({4096, 1, 1}, kLightCacheAuto), 32);
    EXPECT_EQ(lightCacheStride({256, 256, 256}, 0), 0);
    EXPECT_EQ(lightCacheStride({256, 256, 256}, 8), 8);
    OctreeRenderOptions o = phantomOptions();
    o.lightCacheStride = -2;
    auto bad = fillLightCache(phantom256(), o);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("light cache stride"), std::string::npos);
}

// A slab of uniform medium under a sun straight above: every corner inside sees
// T = (1 - a)^(depth below the top), stored as the optical depth -ln T.
TEST(OctreeLightCache, CornersHoldTheExactTransmittance) {
    Volume v = *Volume::create({32, 32, 32});
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 32; ++x) v.set(x, y, z, 128);
    const Octree tree = *buildOctree(v);
    OctreeRenderOptions o;
    o.mode = OctreeMode::Volume;
    o.opacityScale = 0.25f;
    o.sunDirection = {0, 1, 0};
    o.lightCacheStride = 4;
    auto cache = fillLightCache(tree, o);
    ASSERT_TRUE(cache.ok()) << cache.error().message();
    // ceil(31 / 4) = 8 cells per axis between the first and last voxel centres.
    ASSERT_EQ(cache->values.size(), 9u * 9u * 9u);
    const double a = 128.0 / 255.0 * 0.25;
    for (int k = 1; k < 8; ++k)
        for (int j = 0; j < 9; ++j)
            for (int i = 1; i < 8; ++i) {
                const double y = 0.5 + j * 31.0 / 8.0;
                const double expected = std::pow(1 - a, std::max(16 - y, 0.0));
                EXPECT_NEAR(std::exp(-cache->values[i + 9 * (j + 9 * k)]), expected, 1e-5)
                    << i << " " << j << " " << k;
            }
    o.lightCacheStride = 0;
    auto none = fillLightCache(tree, o);
    ASSERT_TRUE(none.ok());
    EXPECT_EQ(none->stride, 0);
    EXPECT_TRUE(none->values.empty());
}

TEST(OctreeLightCache, ARenderReusesAMatchingCacheAndRefillsAStaleOne) {
    const Octree tree = *buildOctree(*makePhantom(48));
    const voxel::Camera camera = *voxel::Camera::lookAt({90, 60, -50}, {24, 24, 24}, 40, 32, 24);
    OctreeRenderOptions o = phantomOptions();
    o.opacityScale = 0.4f;
    OctreeLightCache cache;
    const Image first = *renderOctree(tree, camera, o, &cache);
    ASSERT_TRUE(cache.matches(tree, o));
    EXPECT_EQ(cache.stride, 1);
    EXPECT_EQ(cache.values.size(), 48u * 48u * 48u);  // a corner at every voxel centre
    // A matching cache is read as it is (here made all dark), one marked as another light's is
    // refilled.
    const std::vector<float> values = cache.values;
    std::fill(cache.values.begin(), cache.values.end(), 8.0f);
    const Image stale = *renderOctree(tree, camera, o, &cache);  // matches: read as it is
    const double staleError = compareImages(stale, first)->relativeL1;
    EXPECT_GT(staleError, 0.05);
    cache.opacityScale = -1;
    const Image refilled = *renderOctree(tree, camera, o, &cache);
    EXPECT_EQ(cache.values, values);
    EXPECT_EQ(compareImages(refilled, first)->relativeL1, 0.0);
    o.sunDirection = {-0.5f, 0.8f, 0.3f};
    EXPECT_FALSE(cache.matches(tree, o));
    const Image moved = *renderOctree(tree, camera, o, &cache);
    EXPECT_TRUE(cache.matches(tree, o));
    EXPECT_NE(cache.values, values);
    EXPECT_GT(compareImages(moved, first)->relativeL1, 0.01);
}

// The cached render against the exact one (a shadow ray at every sample) on the 256^3 phantom.
TEST(OctreeLightCache, CachedRenderIsCloseToTheExactOneOnThePhantom) {
    const voxel::Camera camera =
        *voxel::Camera::lookAt({420, 300, -220}, {128, 128, 128}, 40, 64, 48);
    OctreeRenderOptions o = phantomOptions();
    o.lightCacheStride = 0;
    const Image exact = *renderOctree(phantom256(), camera, o);
    struct Case {
        int stride;
        double bound;
    };
    for (const Case& c : {Case{2, 0.005}, Case{4, 0.01}}) {
        o.lightCacheStride = c.stride;
        const Image cached = *renderOctree(phantom256(), camera, o);
        const double error = compareImages(cached, exact)->relativeL1;
        std::printf(
            "phantom 64x48, light cache stride %d: relative L1 %.4f vs exact (bound %.3f)\n",
            c.stride, error, c.bound);
        EXPECT_LT(error, c.bound) << "stride " << c.stride;
        EXPECT_GT(error, 0.0) << "the cache must have been used";
    }
}

TEST(OctreeLightCache, GpuPassMatchesTheCpuTwin) {
    if (!test::sharedGpuContext())
        GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    const Octree tree = *buildOctree(*makePhantom(48));
    const voxel::Camera camera = *voxel::Camera::lookAt({90, 60, -50}, {24, 24, 24}, 40, 64, 48);
    auto uploaded = OctreeGpu::create(*test::sharedGpuContext(), tree);
    ASSERT_TRUE(uploaded.ok()) << uploaded.error().message();
    OctreeRenderOptions o = phantomOptions();
    o.opacityScale = 0.4f;
    for (int stride : {1, 3}) {
        o.lightCacheStride = stride;
        auto cpu = fillLightCache(tree, o);
        auto gpu = uploaded->lightCache(o);
        ASSERT_TRUE(cpu.ok() && gpu.ok());
        ASSERT_EQ(gpu->size(), cpu->values.size());
        double worst = 0;
        int dark = 0;
        for (std::size_t i = 0; i < gpu->size(); ++i) {
            worst = std::max(worst, std::fabs(double((*gpu)[i]) - cpu->values[i]));
            dark += cpu->values[i] < 0.5f ? 1 : 0;
        }
        EXPECT_LT(worst, 1e-3) << "stride " << stride;  // float vs double chords
        EXPECT_GT(dark, 100);                           // the medium shadows part of the grid
        auto cpuImage = renderOctree(tree, camera, o);
        auto gpuImage = uploaded->render(camera, o);
        ASSERT_TRUE(cpuImage.ok() && gpuImage.ok());
        EXPECT_LT(compareImages(*gpuImage, *cpuImage)->relativeL1, 1e-2) << "stride " << stride;
    }
    EXPECT_EQ(test::sharedGpuContext()->validationMessages(), 0)
        << test::sharedGpuContext()->lastValidationMessage();
}

// OctreeGpu keeps the cache while the sun, the opacity scale and the stride stay.
TEST(OctreeLightCache, GpuFillsTheCacheOnlyWhenTheLightChanges) {
    if (!test::sharedGpuContext())
        GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    const Octree tree = *buildOctree(*makePhantom(32));
    auto uploaded = OctreeGpu::create(*test::sharedGpuContext(), tree);
    ASSERT_TRUE(uploaded.ok()) << uploaded.error().message();
    OctreeRenderOptions o = phantomOptions();
    auto fills = [&](const voxel::Camera& camera) {
        std::vector<gpu::PassTiming> timings;
        EXPECT_TRUE(uploaded->render(camera, o, &timings).ok());
        return std::count_if(timings.begin(), timings.end(), [](const gpu::PassTiming& t) {
            return t.name == "octree light cache";
        });
    };
    const voxel::Camera a = *voxel::Camera::lookAt({60, 40, -30}, {16, 16, 16}, 40, 16, 12);
    const voxel::Camera b = *voxel::Camera::lookAt({-30, 40, 60}, {16, 16, 16}, 40, 16, 12);
    EXPECT_EQ(fills(a), 1);
    EXPECT_EQ(fills(b), 0);
    o.sunDirection = {0.1f, 1.0f, 0.2f};
    EXPECT_EQ(fills(b), 1);
    o.opacityScale = 0.3f;
    EXPECT_EQ(fills(b), 1);
    o.lightCacheStride = 4;
    EXPECT_EQ(fills(a), 1);
    EXPECT_EQ(fills(a), 0);
    o.scattering = false;
    EXPECT_EQ(fills(a), 0);
}

}  // namespace
}  // namespace luxel::octree
