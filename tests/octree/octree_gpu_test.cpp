// The GPU octree cast pass against its CPU twin, ray by ray (octree_gpu.h vs octree_trace.h).
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "luxel/gpu/context.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_gpu.h"
#include "support/gpu_test_context.h"

namespace luxel::octree {
namespace {

// Origins on a quarter grid and power-of-two direction components keep every product exact in
// float and double, so ties resolve alike and hits, faces, t, steps and entries must agree.
TEST(OctreeCastParity, GpuPassMatchesTheCpuTwinRayByRay) {
    if (!test::sharedGpuContext())
        GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    Volume v = *Volume::create({64, 40, 72}, true);
    std::mt19937 rng(3);
    for (int z = 0; z < 72; ++z) {
        for (int x = 0; x < 64; ++x) {
            const int h = (x * 7 + z * 3) % 23 + 4;
            for (int y = 0; y < h; ++y) {
                v.set(x, y, z, static_cast<std::uint8_t>(y < 6 ? 255 : 60 + 8 * (y % 20)),
                      Colour{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 9, 1});
            }
        }
    }
    for (int i = 0; i < 300; ++i) {
        v.set(static_cast<int>(rng() % 64), 4 + static_cast<int>(rng() % 30),
              static_cast<int>(rng() % 72), 200, Colour{255, 0, 0, 1});
    }
    auto tree = buildOctree(v);
    ASSERT_TRUE(tree.ok());
    const double dyadic[] = {0.0, 0.25, -0.25, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0, 4.0, -4.0};
    std::vector<voxel::Ray> rays;
    for (int i = 0; i < 5000; ++i) {
        const Vec3d origin{static_cast<double>(rng() % 64) + 0.25 * (i % 4), 36.0 + (i % 5),
                           static_cast<double>(rng() % 72) * 1.125 - 2.0};
        const Vec3d direction{dyadic[rng() % 11], -dyadic[3 + 2 * (i % 3)], dyadic[rng() % 11]};
        rays.push_back({origin, direction});
    }
    auto gpuTree = OctreeGpu::create(*test::sharedGpuContext(), *tree);
    ASSERT_TRUE(gpuTree.ok()) << gpuTree.error().message();
    for (std::uint8_t threshold : {std::uint8_t{1}, std::uint8_t{150}}) {
        const TraceOptions options{.threshold = threshold};
        const std::vector<OctreeHit> cpu = castRays(*tree, rays, options);
        auto gpuHits = gpuTree->castRays(rays, options);
        ASSERT_TRUE(gpuHits.ok()) << gpuHits.error().message();
        int hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const OctreeHit& c = cpu[i];
            const OctreeHit& g = (*gpuHits)[i];
            ASSERT_EQ(g.hit.hit, c.hit.hit) << "ray " << i;
            EXPECT_EQ(g.hit.steps, c.hit.steps) << "ray " << i;
            if (!c.hit.hit) continue;
            ++hits;
            EXPECT_EQ(g.hit.voxel, c.hit.voxel) << "ray " << i;
            EXPECT_EQ(g.hit.normal, c.hit.normal) << "ray " << i;
            EXPECT_EQ(g.hit.t, c.hit.t) << "ray " << i;
            EXPECT_EQ(g.entry, c.entry) << "ray " << i;
        }
        EXPECT_GT(hits, 2000);
    }
    EXPECT_EQ(test::sharedGpuContext()->validationMessages(), 0)
        << test::sharedGpuContext()->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::octree
