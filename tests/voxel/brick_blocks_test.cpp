// Jumps over the empty halves of non-empty bricks (src/voxel/brick_blocks.h, taken by the SIMD
// walk): the half masks against the brick's cells, and castRay, occluded and the batch calls
// against the plain per-voxel DDA (every field but `steps`) and the shared kernel (every field,
// `steps` included) on random worlds whose bricks are partly filled, with tMax and step caps that
// end rays inside a half, partial bricks at the world's far sides and voxels removed after
// the reach was computed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "luxel/voxel/dda.h"
#include "voxel/brick_blocks.h"
#include "voxel/lane_walk.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kStone{90, 90, 90, 255};

// Each half mask holds exactly the 32 cells of its half.
TEST(VoxelBrickBlocks, HalfMasksHoldTheirHalves) {
    const std::uint64_t* halves[3] = {blocks::kHalfX, blocks::kHalfY, blocks::kHalfZ};
    for (int a = 0; a < 3; ++a) {
        for (int side = 0; side < 2; ++side) {
            std::uint64_t expected = 0;
            for (int z = 0; z < 4; ++z) {
                for (int y = 0; y < 4; ++y) {
                    for (int x = 0; x < 4; ++x) {
                        const int c[3] = {x, y, z};
                        if ((c[a] >> 1) == side) {
                            expected |= std::uint64_t{1} << VoxelWorld::brickBit(x, y, z);
                        }
                    }
                }
            }
            EXPECT_EQ(halves[a][side], expected) << a << " " << side;
        }
    }
    // A 6-connected walk through a 4x2x4 box visits at most 4 + 2 + 4 - 2 cells.
    EXPECT_EQ(blocks::kMaxVisits, 8);
}

// boxBits holds exactly the cells of its box, for every box of a brick.
TEST(VoxelBrickBlocks, BoxBitsHoldTheirBox) {
    int boxes = 0;
    for (int code = 0; code < 4096; ++code) {
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = (code >> (4 * a)) & 3;
            hi[a] = (code >> (4 * a + 2)) & 3;
        }
        if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) continue;
        std::uint64_t expected = 0;
        for (int z = lo[2]; z <= hi[2]; ++z) {
            for (int y = lo[1]; y <= hi[1]; ++y) {
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    expected |= std::uint64_t{1} << VoxelWorld::brickBit(x, y, z);
                }
            }
        }
        EXPECT_EQ(blocks::boxBits(lo, hi), expected) << code;
        ++boxes;
    }
    EXPECT_EQ(boxes, 1000);  // (4 + 3 + 2 + 1)^3
}

// Random voxels of a given density in random bricks, plus ground layers of uneven height: bricks
// that are partly full, so many visits inside them are in empty halves.
VoxelWorld randomWorld(Int3 size, std::uint64_t seed) {
    VoxelWorld world = VoxelWorld::create(size, 8).value();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int z = 0; z < size.z; ++z) {
        for (int x = 0; x < size.x; ++x) {
            const int ground = static_cast<int>(size.y * (0.2 + 0.1 * unit(rng)));
            for (int y = 0; y < ground; ++y) world.set(x, y, z, kStone);
        }
    }
    const int scattered = size.x * size.y * size.z / 200;
    for (int i = 0; i < scattered; ++i) {
        world.set(static_cast<int>(unit(rng) * size.x), static_cast<int>(unit(rng) * size.y),
                  static_cast<int>(unit(rng) * size.z), kStone);
    }
    world.refreshEmptySpace();
    return world;
}

std::vector<Ray> randomRays(Int3 size, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double dyadic[] = {0.0, 0.25, -0.25, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0};
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        Vec3d origin, direction;
        for (int a = 0; a < 3; ++a) {
            if (i % 3 == 0) {
                // On a quarter grid with power-of-two directions: exact edge and corner ties.
                origin[a] = std::floor(unit(rng) * (size[a] + 8) - 4) + 0.25 * (i % 4);
                direction[a] = dyadic[rng() % 9];
            } else {
                origin[a] = -6.0 + unit(rng) * (size[a] + 12.0);
                direction[a] = unit(rng) * 2.0 - 1.0;
            }
        }
        if (direction == Vec3d{}) direction.y = -1.0;
        rays.push_back({origin, direction});
    }
    return rays;
}

// castRay, occluded and the batch calls against the plain per-voxel walk and the shared kernel.
// `hits`: how many rays hit.
void compareAll(const VoxelWorld& world, const std::vector<Ray>& rays, double tMax, int stepCap,
                int& hits) {
    std::vector<Hit> batch(rays.size());
    std::vector<std::uint8_t> blocked(rays.size());
    castRayBatch(world, rays, batch, tMax, stepCap);
    occludedBatch(world, rays, blocked, tMax, stepCap);
    const std::vector<Hit> lanes = castRayLanes(world, rays, tMax, stepCap);
    hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Hit mine = castRay(world, rays[i], tMax, stepCap);
        const Hit shared = castRayShared(world, rays[i], tMax, stepCap);
        const Hit* fast[] = {&mine, &batch[i], &lanes[i]};
        for (const Hit* h : fast) {
            ASSERT_EQ(h->hit, shared.hit) << "ray " << i;
            ASSERT_EQ(h->capped, shared.capped) << "ray " << i;
            ASSERT_EQ(h->steps, shared.steps) << "ray " << i;
            ASSERT_EQ(h->voxel, shared.voxel) << "ray " << i;
            ASSERT_EQ(h->normal, shared.normal) << "ray " << i;
            ASSERT_EQ(h->t, shared.t) << "ray " << i;
            ASSERT_EQ(h->point, shared.point) << "ray " << i;
            ASSERT_EQ(h->u, shared.u) << "ray " << i;
            ASSERT_EQ(h->v, shared.v) << "ray " << i;
        }
        ASSERT_EQ(occluded(world, rays[i], tMax, stepCap), shared.hit) << "ray " << i;
        ASSERT_EQ(blocked[i] != 0, shared.hit) << "ray " << i;
        if (stepCap == 0) {
            // Without a cap, the plain per-voxel walk finds the same voxel, face and t.
            const Hit plain = castRay(world, rays[i], tMax, 0, ChunkSkip::Disabled);
            ASSERT_EQ(mine.hit, plain.hit) << "ray " << i;
            ASSERT_EQ(mine.voxel, plain.voxel) << "ray " << i;
            ASSERT_EQ(mine.normal, plain.normal) << "ray " << i;
            ASSERT_EQ(mine.t, plain.t) << "ray " << i;
            ASSERT_EQ(mine.point, plain.point) << "ray " << i;
        }
        hits += shared.hit;
    }
}

TEST(VoxelBrickBlocks, CastsMatchThePlainWalkOnRandomWorlds) {
    // Sides that are not multiples of 4: the last bricks are partial.
    for (const Int3 size : {Int3{48, 40, 44}, Int3{37, 29, 51}, Int3{23, 61, 18}}) {
        const VoxelWorld world = randomWorld(size, static_cast<std::uint64_t>(size.x));
        const std::vector<Ray> rays = randomRays(size, 6000, static_cast<std::uint64_t>(size.y));
        int hits = 0;
        compareAll(world, rays, kInfinity, 0, hits);
        EXPECT_GT(hits, 1000) << size.x;
    }
}

// tMax and caps that end the per-voxel walk inside an empty half: the jump must not be
// taken there, so the miss and its `steps` are the per-voxel loop's.
TEST(VoxelBrickBlocks, TMaxAndStepCapEndRaysInsideHalves) {
    const Int3 size{40, 36, 40};
    const VoxelWorld world = randomWorld(size, 3);
    const std::vector<Ray> rays = randomRays(size, 3000, 4);
    int hits = 0;
    for (const double tMax : {0.3, 1.7, 4.0, 9.5}) compareAll(world, rays, tMax, 0, hits);
    EXPECT_GT(hits, 100);
    int capped = 0;
    for (const int cap : {1, 2, 3, 5, 8, 13}) {
        compareAll(world, rays, kInfinity, cap, hits);
        for (const Ray& r : rays) capped += castRay(world, r, kInfinity, cap).capped;
    }
    EXPECT_GT(capped, 3000);
}

// Removing voxels keeps the reach current (only conservative), so the jumps run on the
// changed masks: halves that just became empty are crossed, and still exactly.
TEST(VoxelBrickBlocks, RemovedVoxelsAreCrossedExactly) {
    const Int3 size{44, 40, 44};
    VoxelWorld world = randomWorld(size, 8);
    std::mt19937_64 rng(9);
    for (int i = 0; i < 4000; ++i) {
        world.set(static_cast<int>(rng() % size.x), static_cast<int>(rng() % size.y),
                  static_cast<int>(rng() % size.z), Voxel{});
    }
    ASSERT_TRUE(world.emptySpaceCurrent());
    int hits = 0;
    compareAll(world, randomRays(size, 5000, 10), kInfinity, 0, hits);
    EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace luxel::voxel
