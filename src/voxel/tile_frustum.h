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

// What the frustum walk needs of a tile's rays: their shared origin, the main axis m they move
// along in direction sgn, and on the other axes the bounds [lo, hi] of the slopes d_a / |d_m|.
// ok: the rays qualify (they share one origin, are finite, all move along m in direction sgn,
// every slope within the limit).
struct TileRays {
    bool ok = false;
    int m = 0, sgn = 1;
    double o[3] = {}, lo[3] = {}, hi[3] = {};
};

// The main axis of a direction: its largest component, the lowest axis on ties.
inline int mainAxis(const Vec3d& d) {
    const double x = d.x < 0.0 ? -d.x : d.x, y = d.y < 0.0 ? -d.y : d.y, z = d.z < 0.0 ? -d.z : d.z;
    return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
}

// The bounds of `rays` about the main axis of the first ray's direction, or about axis m in
// direction sgn when m >= 0 (one pass over the rays, one division each).
TileRays tileRays(std::span<const Ray> rays, int m = -1, int sgn = 1);

// The bounds of two runs of rays about the same axis, read as one tile (the first's origin).
TileRays mergeTileRays(const TileRays& a, const TileRays& b);

// The skip shared by every ray of `tile`, or none where the tile does not qualify: the rays
// must share one origin, be finite, and move the same way along one axis; from inside the world
// the slabs are walked from the origin's own (§4.6 "From inside").
// Conservative: every cell that any of the rays visits before the plane is empty.
// With `from` (a skip of a tile that holds these rays), the walk begins at that skip's plane: the
// cells before it are empty for every ray of that tile.
Skip tileSkip(const VoxelWorld& world, std::span<const Ray> tile, Skip from = {});

// tileSkip for rays whose bounds are already read (tileRays): the same plane.
Skip tileSkip(const VoxelWorld& world, const TileRays& rays, Skip from = {});

}  // namespace luxel::voxel::stream
