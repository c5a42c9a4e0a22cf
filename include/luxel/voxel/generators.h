// Procedural voxel worlds: fBm terrain with optional caves, random fill, spheres and boxes.
#pragma once

#include <cstdint>
#include <optional>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Heightfield terrain from 2D fBm gradient noise (improved Perlin noise, Perlin 2002), coloured in
// bands by height (water, sand, grass, rock, snow) with steep slopes as rock.
struct TerrainOptions {
    std::uint64_t seed = 1;
    double baseHeight = 0.35;  // mean ground height, as a fraction of the world height
    double amplitude = 0.25;   // height variation (+-), as a fraction of the world height
    double frequency = 0.01;   // noise cycles per voxel of the first octave
    int octaves = 5;           // 1..16
    double lacunarity = 2.0;   // frequency factor between octaves, 1..4
    double gain = 0.5;         // amplitude factor between octaves, (0, 1]
    // Water fills the air below this fraction of the height (0: none); sand lines its shore.
    double waterLevel = 0.3;
    double rockLine = 0.6;   // ground above this fraction of the height is rock
    double snowLine = 0.75;  // ground above this fraction of the height is snow
    // A height difference to a neighbour column of at least this many voxels makes rock.
    int steepSlope = 3;
    // Caves: voxels where 3D fBm exceeds caveThreshold are carved out (the bottom layer and the
    // top 3 layers of the ground stay, so caves do not open the surface or the floor).
    bool caves = false;
    double caveFrequency = 0.05;
    double caveThreshold = 0.3;  // in (-1, 1); higher = fewer caves
};

// Every generator leaves the world's brick reach current (VoxelWorld::refreshEmptySpace).

// Checks every option (NaN, out of range) and returns an Error naming the option.
Status validateTerrainOptions(const TerrainOptions& options);

// Replaces the world's contents with terrain. Deterministic by seed and independent of the
// thread count: columns are computed in parallel, each from its own coordinates only.
Status generateTerrain(VoxelWorld& world, const TerrainOptions& options);

// Replaces the world's contents: every voxel is solid with probability `density` (in [0, 1]),
// decided by a hash of (seed, x, y, z), so the result does not depend on the thread count.
// Solid voxels get `colour` (its alpha is forced to at least 1), or a random opaque colour per
// voxel when `colour` is empty.
Status fillRandom(VoxelWorld& world, double density, std::uint64_t seed,
                  std::optional<Voxel> colour = std::nullopt);

// Sets every voxel whose centre (i + 0.5, j + 0.5, k + 0.5) lies inside the closed ball to `v`
// (a voxel with a = 0 carves). Parts outside the world are clipped; a NaN or negative radius
// sets nothing.
void addSphere(VoxelWorld& world, Vec3 centre, float radius, Voxel v);

// Sets every voxel in [min, maxExclusive) to `v`, clipped to the world.
void addBox(VoxelWorld& world, Int3 min, Int3 maxExclusive, Voxel v);

}  // namespace luxel::voxel
