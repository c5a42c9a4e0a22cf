// A test world for proofs about rays: generated terrain with blocks floating over it, so rays
// leave faces of every orientation and meet overhangs (ShadowBlockers, SunRayMap).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "luxel/core/vec.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Terrain of `size` from `seed`, and `blocks` stone voxels at random above its lowest third.
inline VoxelWorld terrainWithBlocks(Int3 size, std::uint64_t seed, int blocks) {
    constexpr Voxel kStone{128, 128, 128, 255};
    VoxelWorld world = VoxelWorld::create(size, 16).value();
    TerrainOptions options;
    options.seed = seed;
    options.frequency = 0.05;
    EXPECT_TRUE(generateTerrain(world, options).ok());
    std::mt19937 rng(static_cast<unsigned>(seed));
    std::uniform_int_distribution<int> x(0, size.x - 1), y(size.y / 3, size.y - 1),
        z(0, size.z - 1);
    for (int i = 0; i < blocks; ++i) world.set(x(rng), y(rng), z(rng), kStone);
    world.refreshEmptySpace();
    return world;
}

inline Vec3d normalised(Vec3d v) {
    return v * (1.0 / std::sqrt(dot(v, v)));
}

}  // namespace luxel::voxel
