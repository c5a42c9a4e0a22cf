// Where the voxel radiance cascades put their probes and how far each level's rays reach
// (docs/algorithms/voxel-radiance-cascades.md §2).
//
// Level 0 of the world cascades has probes every `spacing` voxels (probe i of an axis at
// i spacing + offset(), a voxel centre, so no probe lies in the plane of a face) and side-4
// direction bins; each level above doubles the spacing and the bins per side (4x the directions,
// 1/8 the probes: half the rays). A level's segments start tStart = 1.5 x its spacing from its
// probes and end where the next level's start; the top level's go on until they leave the world.
// Below level 0 are the surface probes (the faces), whose segments run from the face to level 0's
// starts.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"

namespace luxel::voxel::cascades {

inline constexpr int kFaceBinSide = 8;  // direction bins per side at the faces and at level 0
inline constexpr double kStartPerSpacing = 1.5;

struct Level {
    int spacing = 2;
    Int3 probes;  // per axis
    int binSide = kFaceBinSide;
    double tStart = 3.0;
    bool top = false;

    std::int64_t probeCount() const { return std::int64_t(probes.x) * probes.y * probes.z; }
    Int3 probeCell(std::int64_t probe) const;
    double offset() const;  // floor(spacing / 2) + 1/2: probes sit at voxel centres
    Vec3d position(std::int64_t probe) const;
};

// The eight probes of `level` around `point` with trilinear weights (clamped to the grid, so
// points outside it take the border probes).
struct Corners {
    std::array<std::int32_t, 8> probe{};
    std::array<float, 8> weight{};
};
Corners cornersAround(const Level& level, Vec3d point);

// Levels for a world of `worldSize` voxels with level-0 spacing `spacing` (a power of two):
// levels are added until one has at most two probes along the world's longest side.
std::vector<Level> planLevels(Int3 worldSize, int spacing);

// Bytes the cascades need: segment codes (4 B), radiance and child means (12 B per entry) for
// the levels, and `faces` surface probes that each see `binsPerFace` direction bins, with their
// segments and radiance.
std::uint64_t cascadeBytes(const std::vector<Level>& levels, std::int64_t faces, int binsPerFace);

}  // namespace luxel::voxel::cascades
