// The start of a camera sub-tile's walks, a SIMD vector of rays at once (tile_start.cpp): each
// ray's voxelStart and its jump to the tile's skip plane (skip_jump.h), which the one-ray loop
// (fast::walkFrom) then goes on from (docs/algorithms/voxel-traversal.md §4.6, "Starts in lanes").
#pragma once

#include <cstdint>
#include <span>

#include "luxel/voxel/dda.h"
#include "voxel/tile_frustum.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel::stream {

// What the start made of a ray: voxelStart missed the world (a miss, no step), the jump left the
// world or passed tMax (a miss, one step), the jump was taken (one step, `walk` after it), the
// start cell lies at or past the plane (no step, `walk` voxelStart's), or the ray is left to
// fast::traverse (a zero or denormal direction component, or an origin inside the world).
enum class PlaneStart : std::uint8_t { StartMissed, JumpMissed, Jumped, NotTaken, OneRay };

// The most rays one call takes.
inline constexpr std::size_t kMaxStartRays = 16;

// For each of `rays` (finite, at most kMaxStartRays, sharing nothing required) and a skip with
// axis >= 0: walks[i] and starts[i] as traverse<true> computes them, bit for bit.
void startAtPlane(const VoxelWorld& world, std::span<const Ray> rays, Skip skip, double tMax,
                  gpu::shared::VoxelWalk* walks, PlaneStart* starts);

}  // namespace luxel::voxel::stream
