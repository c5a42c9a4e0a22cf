// The tile frustum skip for camera rays (docs/algorithms/voxel-traversal.md §4.6): rays that share
// an origin (outside the world or inside it) and come from one small screen tile form a thin
// frustum; walking it once, slab by slab along its main axis, finds a plane before which no ray
// of the tile meets a solid voxel. Each ray's exact walk then begins with one jump to that plane
// (skip_jump.h, taken by fast::traverse<true>).
#pragma once

#include <span>

#include "luxel/voxel/dda.h"

namespace luxel::voxel::stream {

// Where a ray's walk may begin: the plane `axis` = `plane` (a cell boundary), crossed after the
// ray's entry into the world. axis < 0: no skip, the walk begins at the entry.
struct Skip {
    int axis = -1;
    int plane = 0;
    // The plane is the world's far face: no ray of the tile meets a solid voxel in the world.
    bool clear = false;
};

// The skip shared by every ray of `tile`, or none where the tile does not qualify: the rays
// must share one origin, be finite, and move the same way along one axis; from inside the world
// the slabs are walked from the origin's own (§4.6 "From inside").
// Conservative: every cell that any of the rays visits before the plane is empty.
// With `from` (a skip of a tile that holds these rays), the walk begins at that skip's plane: the
// cells before it are empty for every ray of that tile.
Skip tileSkip(const VoxelWorld& world, std::span<const Ray> tile, Skip from = {});

}  // namespace luxel::voxel::stream
