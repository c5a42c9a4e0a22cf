// The voxel DDA against an outside oracle: Embree intersecting the world's exposed voxel faces as
// quads. Same rays, same hit voxel and t (Embree works in float, hence the tolerance).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "luxel/core/rng.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/generators.h"
#include "voxel/embree_faces.h"

namespace luxel::voxel {
namespace {

VoxelWorld terrainWorld() {
    VoxelWorld world = VoxelWorld::create({96, 48, 96}, 16).value();
    TerrainOptions options;
    options.seed = 5;
    options.frequency = 0.03;
    EXPECT_TRUE(generateTerrain(world, options).ok());
    addSphere(world, {48, 36, 48}, 6, {200, 200, 200, 255});
    return world;
}

TEST(VoxelEmbreeOracle, TerrainRaysHitTheSameVoxel) {
    const VoxelWorld world = terrainWorld();
    const FaceScene oracle(world);
    Pcg32 rng(21);
    int agree = 0, total = 0, tOff = 0;
    for (int i = 0; i < 20000; ++i) {
        // From above and around the terrain, in random downward-ish directions.
        const Vec3d origin{rng.nextDouble() * 140 - 22, 40 + rng.nextDouble() * 30,
                           rng.nextDouble() * 140 - 22};
        Vec3d dir{rng.nextDouble() * 2 - 1, -rng.nextDouble(), rng.nextDouble() * 2 - 1};
        dir = normalize(dir);
        const Ray ray{origin, dir};
        const Hit mine = castRay(world, ray);
        const auto theirs = oracle.cast(ray);
        ++total;
        if (mine.hit != theirs.hit) continue;
        if (!mine.hit || mine.voxel == theirs.voxel) ++agree;
        if (mine.hit && std::abs(mine.t - theirs.t) > 1e-3 * std::max(1.0, mine.t)) ++tOff;
    }
    std::printf("terrain: %d of %d rays agree with Embree (%zu faces), %d with t off\n", agree,
                total, oracle.faces(), tOff);
    EXPECT_GE(agree, static_cast<int>(0.999 * total));
    EXPECT_LE(tOff, total / 1000);
}

TEST(VoxelEmbreeOracle, AxisAlignedAndDiagonalRaysAgreeExactly) {
    const VoxelWorld world = terrainWorld();
    const FaceScene oracle(world);
    int checked = 0;
    auto check = [&](const Ray& ray) {
        const Hit mine = castRay(world, ray);
        const auto theirs = oracle.cast(ray);
        ASSERT_EQ(mine.hit, theirs.hit);
        if (!mine.hit) return;
        ASSERT_EQ(mine.voxel, theirs.voxel);
        ASSERT_NEAR(mine.t, theirs.t, 1e-4 * std::max(1.0, mine.t));
        ++checked;
    };
    // Straight down through every column centre, and along +-x / +-z through row centres.
    for (int z = 0; z < 96; z += 3) {
        for (int x = 0; x < 96; x += 3) check({{x + 0.5, 60.0, z + 0.5}, {0.0, -1.0, 0.0}});
    }
    for (int y = 1; y < 40; y += 2) {
        for (int z = 0; z < 96; z += 5) {
            check({{-3.0, y + 0.5, z + 0.5}, {1.0, 0.0, 0.0}});
            check({{99.0, y + 0.5, z + 0.5}, {-1.0, -0.0, 0.0}});
            check({{z + 0.5, y + 0.5, -3.0}, {0.0, 0.0, 1.0}});
        }
    }
    // Exact diagonals. From a voxel centre a (1, -1, 1) ray crosses all three axes at once, at
    // voxel corners, where either neighbour is a correct answer (our tie rule and Embree's float
    // arithmetic may differ); start off that lattice so every crossing is unambiguous.
    const double s = 1.0 / std::sqrt(3.0);
    for (int x = 0; x < 96; x += 7) {
        for (int z = 0; z < 96; z += 7) {
            check({{x + 0.5, 45.3, z + 0.15}, {s, -s, s}});
            check({{x + 0.5, 45.3, z + 0.15}, {-s, -s, -s}});
        }
    }
    EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace luxel::voxel
