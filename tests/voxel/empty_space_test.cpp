// Brick occupancy masks and empty-space distances of VoxelWorld, and exact traversal with them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>

#include "luxel/voxel/dda.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kStone{128, 128, 128, 255};

// Chebyshev distance in bricks from (bx, by, bz) to the nearest brick with a solid voxel.
int bruteForceDistance(const VoxelWorld& world, Int3 b) {
    int best = VoxelWorld::kMaxBrickDistance;
    const Int3 n = world.brickCount();
    for (int z = 0; z < n.z; ++z) {
        for (int y = 0; y < n.y; ++y) {
            for (int x = 0; x < n.x; ++x) {
                if (world.brickMask(x, y, z) == 0) continue;
                const int d = std::max({std::abs(x - b.x), std::abs(y - b.y), std::abs(z - b.z)});
                best = std::min(best, d);
            }
        }
    }
    return best;
}

TEST(VoxelEmptySpace, BrickMasksTrackEveryVoxel) {
    VoxelWorld world = VoxelWorld::create({13, 9, 6}, 8).value();
    world.set(5, 2, 3, kStone);
    EXPECT_EQ(world.brickMask(1, 0, 0), std::uint64_t{1} << VoxelWorld::brickBit(5, 2, 3));
    world.set(7, 3, 0, kStone);
    EXPECT_EQ(world.brickMask(1, 0, 0), (std::uint64_t{1} << (3 * 16 + 2 * 4 + 1)) |
                                            (std::uint64_t{1} << (0 * 16 + 3 * 4 + 3)));
    world.set(5, 2, 3, Voxel{});
    world.set(7, 3, 0, Voxel{1, 2, 3, 0});  // a colour with alpha 0 is empty
    EXPECT_EQ(world.brickMask(1, 0, 0), 0u);
    // Partial bricks at the world's edge.
    world.set(12, 8, 5, kStone);
    EXPECT_EQ(world.brickCount(), (Int3{4, 3, 2}));
    EXPECT_EQ(world.brickMask(3, 2, 1), std::uint64_t{1} << VoxelWorld::brickBit(12, 8, 5));
}

TEST(VoxelEmptySpace, DistancesMatchBruteForce) {
    VoxelWorld world = VoxelWorld::create({70, 50, 90}, 16).value();
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> x(0, 69), y(0, 49), z(0, 89);
    for (int i = 0; i < 12; ++i) world.set(x(rng), y(rng), z(rng), kStone);
    EXPECT_FALSE(world.emptySpaceCurrent());
    world.refreshEmptySpace();
    EXPECT_TRUE(world.emptySpaceCurrent());
    const Int3 n = world.brickCount();
    for (int bz = 0; bz < n.z; ++bz) {
        for (int by = 0; by < n.y; ++by) {
            for (int bx = 0; bx < n.x; ++bx) {
                ASSERT_EQ(world.brickDistance(bx, by, bz), bruteForceDistance(world, {bx, by, bz}))
                    << bx << " " << by << " " << bz;
            }
        }
    }
}

TEST(VoxelEmptySpace, OnlyNewlyOccupiedBricksMakeDistancesStale) {
    VoxelWorld world = VoxelWorld::create({32, 32, 32}, 8).value();
    EXPECT_TRUE(world.emptySpaceCurrent());  // empty: every distance is the cap, which is right
    world.set(3, 3, 3, kStone);
    EXPECT_FALSE(world.emptySpaceCurrent());
    world.refreshEmptySpace();
    world.set(2, 3, 3, kStone);  // same brick: distances unchanged
    EXPECT_TRUE(world.emptySpaceCurrent());
    world.set(3, 3, 3, Voxel{});  // removal: distances only become conservative
    world.set(2, 3, 3, Voxel{});
    EXPECT_TRUE(world.emptySpaceCurrent());
    addSphere(world, {20, 20, 20}, 3, kStone);  // generators refresh when they finish
    EXPECT_TRUE(world.emptySpaceCurrent());
    EXPECT_EQ(world.brickDistance(5, 5, 5), 0);
}

// Traversal must give exactly the per-voxel loop's result whichever jumps it takes: compare the
// three modes (distances current, stale distances = chunk/brick jumps, no jumps) on rays whose
// small integer directions from cell centres and corners create ties inside jumps.
TEST(VoxelEmptySpace, DistanceJumpsMatchPlainTraversal) {
    VoxelWorld world = VoxelWorld::create({96, 80, 96}, 16).value();
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> coord(0, 79);
    for (int i = 0; i < 400; ++i) world.set(coord(rng), coord(rng), coord(rng), kStone);
    addBox(world, {40, 0, 40}, {60, 6, 60}, kStone);  // refreshes the distances
    ASSERT_TRUE(world.emptySpaceCurrent());
    VoxelWorld stale = world;
    stale.set(95, 79, 95, kStone);  // a new brick far from every ray's path below
    stale.set(95, 79, 95, Voxel{});
    ASSERT_FALSE(stale.emptySpaceCurrent());

    std::uniform_int_distribution<int> cell(-3, 99), dir(-3, 3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    long hits = 0, stepsPlain = 0, stepsJump = 0;
    for (int i = 0; i < 8000; ++i) {
        const double offset = i % 3 == 0 ? 0.0 : (i % 3 == 1 ? 0.5 : 0.25);
        const Vec3d origin{cell(rng) + offset, cell(rng) + offset, cell(rng) + offset};
        Vec3d direction{double(dir(rng)), double(dir(rng)), double(dir(rng))};
        if (i % 4 == 1) direction = {unit(rng), unit(rng), unit(rng)};
        if (i % 4 == 3) direction = Vec3d{50.5, 3.5, 50.5} - origin;  // at the box
        const Ray ray{origin, direction};
        const Hit plain = castRay(world, ray, kInfinity, 0, ChunkSkip::Disabled);
        const Hit jumps = castRay(world, ray, kInfinity, 0, ChunkSkip::Enabled);
        const Hit chunks = castRay(stale, ray, kInfinity, 0, ChunkSkip::Enabled);
        for (const Hit* h : {&jumps, &chunks}) {
            ASSERT_EQ(h->hit, plain.hit) << "ray " << i;
            ASSERT_EQ(h->voxel, plain.voxel) << "ray " << i;
            ASSERT_EQ(h->normal, plain.normal) << "ray " << i;
            ASSERT_EQ(h->t, plain.t) << "ray " << i;
            ASSERT_EQ(h->point, plain.point) << "ray " << i;
        }
        hits += plain.hit;
        stepsPlain += plain.steps;
        stepsJump += jumps.steps;
    }
    EXPECT_GT(hits, 2000);  // not vacuous: many rays end on a voxel
    EXPECT_LT(stepsJump * 4, stepsPlain);
}

}  // namespace
}  // namespace luxel::voxel
