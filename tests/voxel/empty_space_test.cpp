// Brick occupancy masks and the directional empty-space reach of VoxelWorld, and exact traversal
// with them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

#include "luxel/voxel/dda.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kStone{128, 128, 128, 255};

// The side of the largest cube of empty bricks with a corner at brick b extending towards
// `octant` (bricks outside the world empty), grown one shell at a time, capped.
int bruteForceReach(const VoxelWorld& world, Int3 b, int octant) {
    const Int3 n = world.brickCount();
    const Int3 sign{(octant & 1) ? -1 : 1, (octant & 2) ? -1 : 1, (octant & 4) ? -1 : 1};
    // Bricks of the world from b towards the octant, per axis: beyond them the cube is outside.
    const Int3 extent{sign.x > 0 ? n.x - b.x : b.x + 1, sign.y > 0 ? n.y - b.y : b.y + 1,
                      sign.z > 0 ? n.z - b.z : b.z + 1};
    for (int side = 1; side <= VoxelWorld::kMaxBrickReach; ++side) {
        if (side - 1 >= std::max({extent.x, extent.y, extent.z})) break;  // all outside from here
        // The shell that grows the cube of side - 1 to this side, where it is in the world.
        for (int k = 0; k < std::min(side, extent.z); ++k) {
            for (int j = 0; j < std::min(side, extent.y); ++j) {
                for (int i = 0; i < std::min(side, extent.x); ++i) {
                    if (std::max({i, j, k}) != side - 1) continue;
                    if (world.brickMask(b.x + sign.x * i, b.y + sign.y * j, b.z + sign.z * k) !=
                        0) {
                        return side - 1;
                    }
                }
            }
        }
    }
    return VoxelWorld::kMaxBrickReach;
}

// Every brick's reach in every octant against bruteForceReach: equal, or (after removals without
// a refresh) never more.
void expectReach(const VoxelWorld& world, bool exact) {
    const Int3 n = world.brickCount();
    for (int o = 0; o < VoxelWorld::kOctants; ++o) {
        for (int bz = 0; bz < n.z; ++bz) {
            for (int by = 0; by < n.y; ++by) {
                for (int bx = 0; bx < n.x; ++bx) {
                    const int truth = bruteForceReach(world, {bx, by, bz}, o);
                    const int reach = world.brickReach(o, bx, by, bz);
                    if (exact) {
                        ASSERT_EQ(reach, truth)
                            << "brick " << bx << " " << by << " " << bz << ", octant " << o;
                    } else {
                        ASSERT_LE(reach, truth)
                            << "brick " << bx << " " << by << " " << bz << ", octant " << o;
                        ASSERT_EQ(reach == 0, world.brickMask(bx, by, bz) != 0);
                    }
                }
            }
        }
    }
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

TEST(VoxelEmptySpace, ReachIsTheLargestEmptyCubePerOctant) {
    // Sides that are not multiples of the brick (partial bricks at the edges), sparse and dense.
    for (const int solids : {3, 25, 400}) {
        VoxelWorld world = VoxelWorld::create({37, 22, 29}, 8).value();
        std::mt19937 rng(solids);
        std::uniform_int_distribution<int> x(0, 36), y(0, 21), z(0, 28);
        std::vector<Int3> placed;
        for (int i = 0; i < solids; ++i) {
            placed.push_back({x(rng), y(rng), z(rng)});
            world.set(placed.back().x, placed.back().y, placed.back().z, kStone);
        }
        EXPECT_FALSE(world.emptySpaceCurrent());
        world.refreshEmptySpace();
        EXPECT_TRUE(world.emptySpaceCurrent());
        expectReach(world, true);
        // Removals keep the reach usable (never more than the truth; an emptied brick reaches 1).
        // Every other placed voxel, and the whole brick of the first one.
        std::vector<Int3> removals;
        for (std::size_t i = 0; i < placed.size(); i += 2) removals.push_back(placed[i]);
        for (int i = 0; i < 64; ++i) {
            removals.push_back({(placed[0].x & ~3) + i % 4, (placed[0].y & ~3) + i / 4 % 4,
                                (placed[0].z & ~3) + i / 16});
        }
        int emptied = 0;
        for (const Int3& v : removals) {
            const int vx = v.x, vy = v.y, vz = v.z;
            if (!world.inside(vx, vy, vz)) continue;
            const bool was = world.brickMask(vx >> 2, vy >> 2, vz >> 2) != 0;
            world.set(vx, vy, vz, Voxel{});
            if (was && world.brickMask(vx >> 2, vy >> 2, vz >> 2) == 0) {
                ++emptied;
                for (int o = 0; o < VoxelWorld::kOctants; ++o) {
                    ASSERT_EQ(world.brickReach(o, vx >> 2, vy >> 2, vz >> 2), 1);
                }
            }
        }
        EXPECT_GT(emptied, 0);
        EXPECT_TRUE(world.emptySpaceCurrent());
        expectReach(world, false);
        // A brick gains a voxel: stale until refreshed.
        const Int3 n = world.brickCount();
        for (int b = 0; b < n.x * n.y * n.z && world.emptySpaceCurrent(); ++b) {
            const int bx = b % n.x, by = b / n.x % n.y, bz = b / (n.x * n.y);
            if (world.brickMask(bx, by, bz) == 0) world.set(4 * bx, 4 * by, 4 * bz, kStone);
        }
        EXPECT_FALSE(world.emptySpaceCurrent());
        world.refreshEmptySpace();
        expectReach(world, true);
    }
}

TEST(VoxelEmptySpace, ReachOfAnEmptyWorldIsTheCap) {
    const VoxelWorld world = VoxelWorld::create({12, 8, 4}, 4).value();
    ASSERT_TRUE(world.emptySpaceCurrent());
    expectReach(world, true);  // outside the world counts as empty: no cube ever ends
    EXPECT_EQ(world.brickReach(5, 2, 1, 0), VoxelWorld::kMaxBrickReach);
}

// Traversal must give exactly the per-voxel loop's result whichever jumps it takes: compare the
// three modes (reach current, stale reach = chunk/brick jumps, no jumps) on rays whose
// small integer directions from cell centres and corners create ties inside jumps.
TEST(VoxelEmptySpace, ReachJumpsMatchPlainTraversal) {
    VoxelWorld world = VoxelWorld::create({96, 80, 96}, 16).value();
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> coord(0, 79);
    for (int i = 0; i < 400; ++i) world.set(coord(rng), coord(rng), coord(rng), kStone);
    addBox(world, {40, 0, 40}, {60, 6, 60}, kStone);  // refreshes the reach
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
