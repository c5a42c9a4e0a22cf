// Empty-space distances over the brick occupancy masks of a VoxelWorld: for every brick, the
// Chebyshev distance (in bricks) to the nearest brick holding a solid voxel. Traversal uses it to
// cross a whole empty box of bricks in one exact jump (the "distance field" acceleration of
// Cohen & Sheffer 1994, "Proximity clouds", at brick granularity).
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"

namespace luxel::voxel {

// `masks` and `distances` are brick-linear (x fastest) over `count` bricks. Distances are capped at
// `cap` (<= 255); bricks outside the grid count as empty.
void computeBrickDistances(const std::vector<std::uint64_t>& masks, Int3 count, int cap,
                           std::vector<std::uint8_t>& distances);

}  // namespace luxel::voxel
