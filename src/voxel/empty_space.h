// Directional empty-space reach over the brick occupancy masks of a VoxelWorld: for every brick and
// each of the 8 direction octants, the side of the largest cube of empty bricks with a corner at
// the brick, extending towards the octant. Traversal crosses that cube in one exact jump (a
// directional form of the "proximity clouds" of Cohen & Sheffer 1994, at brick granularity;
// docs/algorithms/voxel-traversal.md §3).
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"

namespace luxel::voxel {

// `masks` is brick-linear (x fastest) over `count` bricks; `reach` becomes 8 such planes, octant o
// (bit a set: towards -inf on axis a) at o * masks.size(). Sides are capped at `cap` (<= 255);
// bricks outside the grid count as empty.
void computeBrickReach(const std::vector<std::uint64_t>& masks, Int3 count, int cap,
                       std::vector<std::uint8_t>& reach);

}  // namespace luxel::voxel
