// Traversal with the directional brick reach (docs/algorithms/voxel-traversal.md §3) against the
// plain per-voxel walk on random worlds under random edits: every Hit field but `steps` equals the
// plain walk's, and castRay, the shared kernel and the batch calls agree on every field, `steps`
// included (the loop count is one contract for every backend).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "luxel/voxel/dda.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/voxel_world.h"
#include "voxel/lane_walk.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kStone{128, 128, 128, 255};

// Every field but `steps`, which only the plain walk counts differently.
void expectSameHit(const Hit& a, const Hit& plain, int ray) {
    ASSERT_EQ(a.hit, plain.hit) << "ray " << ray;
    ASSERT_EQ(a.capped, plain.capped) << "ray " << ray;
    ASSERT_EQ(a.voxel, plain.voxel) << "ray " << ray;
    ASSERT_EQ(a.normal, plain.normal) << "ray " << ray;
    ASSERT_EQ(a.t, plain.t) << "ray " << ray;
    ASSERT_EQ(a.point, plain.point) << "ray " << ray;
    ASSERT_EQ(a.u, plain.u) << "ray " << ray;
    ASSERT_EQ(a.v, plain.v) << "ray " << ray;
}

struct Totals {
    long hits = 0, stepsPlain = 0, stepsReach = 0;
};

// Rays of several kinds: random, dyadic (exact ties at edges and corners), from outside the
// world, axis-aligned with zero components, and secondary rays from the faces of hits.
std::vector<Ray> randomRays(const VoxelWorld& world, std::mt19937_64& rng, int n) {
    const Int3 size = world.size();
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> pick(0, 8);
    const double dyadic[] = {0.0, 0.25, -0.25, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0};
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
        Vec3d o{unit(rng) * size.x, unit(rng) * size.y, unit(rng) * size.z};
        Vec3d d{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5};
        switch (i % 5) {
            case 1:
                o = {std::floor(o.x) + 0.25 * (i % 4), std::floor(o.y) + 0.5, std::floor(o.z)};
                d = {dyadic[pick(rng)], dyadic[pick(rng)], dyadic[pick(rng)]};
                if (d == Vec3d{}) d.x = 1.0;
                break;
            case 2:  // from outside, at a point inside
                o = {(unit(rng) * 3 - 1) * size.x, size.y * 2.5, (unit(rng) * 3 - 1) * size.z};
                d = Vec3d{unit(rng) * size.x, unit(rng) * size.y, unit(rng) * size.z} - o;
                break;
            case 3:  // zero components
                d[i % 3] = 0.0;
                if (i % 2) d[(i + 1) % 3] = -0.0;
                break;
            case 4: {
                const Hit h = castRay(world, {o, d}, kInfinity, 0, ChunkSkip::Disabled);
                if (h.hit) {
                    o = h.point;
                    d = {unit(rng) - 0.5, unit(rng), unit(rng) - 0.5};
                }
                break;
            }
            default:
                break;
        }
        rays.push_back({o, d});
    }
    return rays;
}

void compareWithPlain(const VoxelWorld& world, const std::vector<Ray>& rays, double tMax,
                      Totals& totals) {
    std::vector<Hit> batch(rays.size());
    std::vector<std::uint8_t> blocked(rays.size());
    castRayBatch(world, rays, batch, tMax, 0);
    occludedBatch(world, rays, blocked, tMax, 0);
    const std::vector<Hit> lanes = castRayLanes(world, rays, tMax, 0);
    for (int i = 0; i < static_cast<int>(rays.size()); ++i) {
        const Hit plain = castRay(world, rays[i], tMax, 0, ChunkSkip::Disabled);
        const Hit fast = castRay(world, rays[i], tMax);
        const Hit shared = castRayShared(world, rays[i], tMax);
        expectSameHit(fast, plain, i);
        expectSameHit(shared, plain, i);
        expectSameHit(batch[i], plain, i);
        expectSameHit(lanes[i], plain, i);
        ASSERT_EQ(fast.steps, shared.steps) << "ray " << i;
        ASSERT_EQ(batch[i].steps, shared.steps) << "ray " << i;
        ASSERT_EQ(lanes[i].steps, shared.steps) << "ray " << i;
        ASSERT_EQ(blocked[i] != 0, plain.hit) << "ray " << i;
        ASSERT_EQ(occluded(world, rays[i], tMax), plain.hit) << "ray " << i;
        totals.hits += plain.hit;
        totals.stepsPlain += plain.steps;
        totals.stepsReach += shared.steps;
    }
}

TEST(VoxelBrickReach, RandomWorldsWithEditsMatchThePlainWalk) {
    std::mt19937_64 rng(77);
    Totals totals;
    for (int trial = 0; trial < 6; ++trial) {
        const Int3 size{41 + 8 * trial, 30 + 5 * trial, 37 + 3 * trial};  // partial edge bricks
        VoxelWorld world = VoxelWorld::create(size, trial % 2 ? 8 : 16).value();
        TerrainOptions terrain;
        terrain.seed = trial;
        terrain.frequency = 0.05;
        ASSERT_TRUE(generateTerrain(world, terrain).ok());
        std::uniform_int_distribution<int> x(0, size.x - 1), y(0, size.y - 1), z(0, size.z - 1);
        for (int round = 0; round < 4; ++round) {
            // Floating voxels and boxes, and holes dug into everything.
            for (int i = 0; i < 40; ++i) world.set(x(rng), y(rng), z(rng), kStone);
            const Int3 corner{x(rng), y(rng), z(rng)};
            for (int i = 0; i < 200; ++i) {
                world.set(corner.x + i % 6, corner.y + i / 6 % 5, corner.z + i / 30, kStone);
            }
            world.refreshEmptySpace();
            ASSERT_TRUE(world.emptySpaceCurrent());
            compareWithPlain(world, randomRays(world, rng, 600), kInfinity, totals);
            // Removals without a refresh: the reach stays current, only conservative.
            for (int i = 0; i < 3000; ++i) world.set(x(rng), y(rng), z(rng), Voxel{});
            ASSERT_TRUE(world.emptySpaceCurrent());
            compareWithPlain(world, randomRays(world, rng, 600), kInfinity, totals);
            compareWithPlain(world, randomRays(world, rng, 300), 9.5, totals);
        }
    }
    EXPECT_GT(totals.hits, 5000);  // not vacuous
    EXPECT_LT(totals.stepsReach * 3, totals.stepsPlain);
}

// A ray grazing a flat floor: the centred box of an empty-space distance would be one brick
// (the floor is one brick away), the reach towards +x and up spans the whole open space ahead,
// so the ray leaves the world in one jump.
TEST(VoxelBrickReach, GrazingRayLeavesInOneJump) {
    VoxelWorld world = VoxelWorld::create({128, 64, 128}, 16).value();
    addBox(world, {0, 0, 0}, {128, 4, 128}, kStone);
    ASSERT_TRUE(world.emptySpaceCurrent());
    const Ray grazing{{0.5, 4.5, 60.5}, {1.0, 0.0, 0.0}};
    for (const Hit& h : {castRay(world, grazing), castRayShared(world, grazing)}) {
        EXPECT_FALSE(h.hit);
        EXPECT_EQ(h.steps, 1);
    }
    // Towards the floor the reach stops at it: one jump to the brick above it, then voxel
    // steps in the floor's brick.
    const Ray down{{0.5, 60.5, 60.5}, {1.0, -1.0, 0.0}};
    const Hit h = castRay(world, down);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.voxel.y, 3);
    EXPECT_LE(h.steps, 4);
    expectSameHit(h, castRay(world, down, kInfinity, 0, ChunkSkip::Disabled), 0);
}

}  // namespace
}  // namespace luxel::voxel
