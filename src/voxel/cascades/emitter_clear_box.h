// An empty box of cells in front of an emitting face, found once with the near lists, that proves
// a near-emitter visibility line clear without its walk (docs/algorithms/voxel-radiance-cascades.md
// §5, "Near lines proven clear"): a line from a point on the box's boundary, not on the emitter's
// plane, to a point strictly inside the emitter's face runs through the box's inside until it
// meets that face, so the walk crosses only empty cells and stops at the face, transmittance 1.
#pragma once

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel::cascades {

struct EmitterClearBox {
    // Cells lo <= c < hi, all empty; lo == hi: none. The emitter's face lies on one side of it.
    Int3 lo, hi;
    Int3 rectLo, rectHi;  // the emitting voxels, rectLo <= c < rectHi (one layer)
    int emitterAxis = 0;
    int emitterPlane = 0;  // the emitter face's coordinate on emitterAxis
    bool empty() const { return !(lo.x < hi.x); }
};

// The box grown from the cells in front of the emitting rectangle with corner voxel `corner`,
// normal index `normal` and sizeA x sizeB voxels along (axis + 1) % 3 and (axis + 2) % 3 (as
// CascadeNearEmitter's extent): one layer at a time towards the five sides away from the face,
// while the new layer is inside the world, empty, and within `reach` cells of the rectangle;
// none when a cell in front of it is solid.
EmitterClearBox growEmitterClearBox(const VoxelWorld& world, Int3 corner, int normal, int sizeA,
                                    int sizeB, int reach);

// Whether faceRayTransmittance from `hit` (a castRay hit: its point snapped onto the face's plane)
// to any point strictly inside the box's emitter face is 1 without a walk: the face's outside
// cell is in the box, the point is within the box's bounds and strictly off the emitter's plane.
// Also needs no cutout texels and castRay's default step cap (the caller's to check).
bool lineProvenClear(const EmitterClearBox& box, const Hit& hit);

// Whether castRay from `hit` along `direction`, which crosses the emitter's plane `reach` along
// it, provably meets the rectangle first, and the voxel of it it enters (`*voxel`): as
// lineProvenClear, the crossing at least ShadowBlockers::kEdgeMargin from every cell edge of the
// rectangle and inside it, so the walk's rounding cannot decide which cell it enters.
bool rayProvenToRect(const EmitterClearBox& box, const Hit& hit, const Vec3d& direction,
                     double reach, Int3* voxel);

}  // namespace luxel::voxel::cascades
