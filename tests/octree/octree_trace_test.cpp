// Exact octree traversal (octree_trace.h): every pixel of a set of cameras hits what the dense
// world's A&W walk hits (voxel, face, entry t), on terrain with caves and floating specks; and
// opacity thresholds stop rays at the first leaf that opaque. The DDA edge-case suite also runs on
// the octree (tests/voxel/dda_test.cpp, backends OctreeCpu and OctreeGpu).
#include <gtest/gtest.h>

#include <random>

#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_trace.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"

namespace luxel::octree {
namespace {

voxel::VoxelWorld caveTerrain() {
    auto world = voxel::VoxelWorld::create({96, 64, 80}, 16);
    voxel::TerrainOptions options;
    options.seed = 9;
    options.caves = true;
    options.caveThreshold = 0.1;
    EXPECT_TRUE(voxel::generateTerrain(*world, options).ok());
    std::mt19937 rng(2);
    for (int i = 0; i < 400; ++i) {
        world->set(static_cast<int>(rng() % 96), 30 + static_cast<int>(rng() % 34),
                   static_cast<int>(rng() % 80), voxel::Voxel{250, 20, 20, 1});
    }
    world->refreshEmptySpace();
    return std::move(*world);
}

TEST(OctreeTrace, EveryPixelOfTheTestCamerasHitsWhatTheDenseWalkHits) {
    const voxel::VoxelWorld world = caveTerrain();
    auto tree = buildOctree(world);
    ASSERT_TRUE(tree.ok());
    struct View {
        Vec3d position, target;
    };
    const View views[] = {
        {{-30, 70, -30}, {48, 20, 40}},        // from outside, above a corner
        {{48, 30, 40}, {90, 10, 70}},          // from inside the world (in caves or air)
        {{48, 100, 40.5}, {48, 0, 40.5}},      // straight down: many axis ties
        {{200, 32, 40}, {0, 32, 40}},          // along -x through the middle
        {{10.5, 45, 10.5}, {80.5, 45, 70.5}},  // a diagonal at a half-integer height
    };
    long hits = 0, pixels = 0, octreeSteps = 0, denseSteps = 0;
    for (const View& v : views) {
        auto camera = voxel::Camera::lookAt(v.position, v.target, 60.0, 96, 64);
        ASSERT_TRUE(camera.ok());
        for (int py = 0; py < 64; ++py) {
            for (int px = 0; px < 96; ++px) {
                const voxel::Ray ray = camera->primaryRay(px, py);
                const voxel::Hit dense = voxel::castRay(world, ray);
                const OctreeHit sparse = castRay(*tree, ray);
                ASSERT_EQ(sparse.hit.hit, dense.hit) << px << "," << py;
                ++pixels;
                denseSteps += dense.steps;
                octreeSteps += sparse.hit.steps;
                if (!dense.hit) continue;
                ++hits;
                ASSERT_EQ(sparse.hit.voxel, dense.voxel) << px << "," << py;
                ASSERT_EQ(sparse.hit.normal, dense.normal);
                ASSERT_EQ(sparse.hit.t, dense.t);
                ASSERT_EQ(sparse.hit.point, dense.point);
                // Voxel worlds build in leaf order: the walk tracks each hit's colour index.
                ASSERT_TRUE(tree->leafOrder());
                ASSERT_EQ(tree->colours[sparse.colourIndex],
                          world.get(dense.voxel.x, dense.voxel.y, dense.voxel.z));
            }
        }
    }
    EXPECT_GT(hits, pixels / 3);
    EXPECT_LT(hits, pixels);
    // Uniform leaves are crossed in one jump: fewer loop iterations than the dense walk with its
    // brick masks and distance jumps needs (deterministic: the same rays every run).
    EXPECT_LT(octreeSteps, denseSteps);
}

TEST(OctreeTrace, ThresholdsStopAtTheFirstLeafThatOpaque) {
    Volume v = *Volume::create({32, 32, 32});
    for (int x = 0; x < 32; ++x) {
        for (int z = 0; z < 32; ++z) {
            for (int y = 0; y < 32; ++y) v.set(x, y, z, static_cast<std::uint8_t>(x * 8));
        }
    }
    auto tree = buildOctree(v);
    ASSERT_TRUE(tree.ok());
    const voxel::Ray ray{{-1.0, 5.5, 5.5}, {1.0, 0.0, 0.0}};
    for (int threshold : {1, 8, 100, 248}) {
        const OctreeHit h =
            castRay(*tree, ray, {.threshold = static_cast<std::uint8_t>(threshold)});
        ASSERT_TRUE(h.hit.hit);
        EXPECT_EQ(h.hit.voxel.x, (threshold + 7) / 8) << threshold;
        EXPECT_EQ(h.hit.t, 1.0 + h.hit.voxel.x);
    }
    EXPECT_FALSE(castRay(*tree, ray, {.threshold = 255}).hit.hit);
    // tMax and the step cap end the ray as in the dense walk.
    EXPECT_FALSE(castRay(*tree, ray, {.tMax = 3.5, .threshold = 100}).hit.hit);
    const OctreeHit capped = castRay(*tree, ray, {.stepCap = 3, .threshold = 100});
    EXPECT_TRUE(capped.hit.capped);
    // Invalid rays never hit.
    EXPECT_FALSE(castRay(*tree, {{0, 0, 0}, {0, 0, 0}}).hit.hit);
    EXPECT_FALSE(castRay(*tree, {{std::nan(""), 0, 0}, {1, 0, 0}}).hit.hit);
}

}  // namespace
}  // namespace luxel::octree
