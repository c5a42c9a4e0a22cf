// A test world for proofs about rays: generated terrain with blocks floating over it, so rays
// leave faces of every orientation and meet overhangs (ShadowBlockers, SunRayMap), and points on
// its faces.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Terrain of `size` from `seed` at noise `frequency`, and `blocks` stone voxels at random from
// height `lowestBlockY` up (-1: a third of the way up).
inline VoxelWorld terrainWithBlocks(Int3 size, std::uint64_t seed, int blocks,
                                    double frequency = 0.05, int lowestBlockY = -1) {
    constexpr Voxel kStone{128, 128, 128, 255};
    VoxelWorld world = VoxelWorld::create(size, 16).value();
    TerrainOptions options;
    options.seed = seed;
    options.frequency = frequency;
    EXPECT_TRUE(generateTerrain(world, options).ok());
    std::mt19937 rng(static_cast<unsigned>(seed));
    std::uniform_int_distribution<int> x(0, size.x - 1),
        y(lowestBlockY < 0 ? size.y / 3 : lowestBlockY, size.y - 1), z(0, size.z - 1);
    for (int i = 0; i < blocks; ++i) world.set(x(rng), y(rng), z(rng), kStone);
    world.refreshEmptySpace();
    return world;
}

inline Vec3d normalised(Vec3d v) {
    return v * (1.0 / std::sqrt(dot(v, v)));
}

// Where a random ray from half a voxel below the world's top, heading down at 17 to 73 degrees
// from the vertical, first meets it: a point on a face the sky can see (hit.hit false on a miss).
inline Hit hitFromAbove(const VoxelWorld& world, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0), signedUnit(-1.0, 1.0);
    const Int3 size = world.size();
    const Vec3d origin{unit(rng) * size.x, size.y - 0.5, unit(rng) * size.z};
    const Vec3d direction = normalised({signedUnit(rng), -0.3 - unit(rng), signedUnit(rng)});
    return castRay(world, {origin, direction});
}

// A point on face `normal` (a unit axis) of `voxel` at (a, b) in [0, 1]^2 across it, on the
// face's plane, as castRay reports a hit there.
inline Hit faceHit(Int3 voxel, Int3 normal, double a, double b) {
    Hit h;
    h.hit = true;
    h.voxel = voxel;
    h.normal = normal;
    const int axis = normal.x != 0 ? 0 : (normal.y != 0 ? 1 : 2);
    h.point = {double(voxel.x), double(voxel.y), double(voxel.z)};
    h.point[axis] += normal[axis] > 0 ? 1.0 : 0.0;
    h.point[(axis + 1) % 3] += a;
    h.point[(axis + 2) % 3] += b;
    return h;
}

}  // namespace luxel::voxel
