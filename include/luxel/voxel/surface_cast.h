// Ray casting that honours cutout texels: a textured voxel whose texel at the hit has alpha < 0.5
// lets the ray through (the Unity voxel ray tracer's ChunkTracer4: "if we hit a transparent pixel,
// loop to the next block as if we hit air"), for primary, reflection and shadow rays alike.
//
// The ray continues by restarting castRay at the point where it leaves the cutout voxel: the
// exit axis (lowest axis on ties, as the DDA steps) is snapped exactly onto the voxel boundary
// and the other axes are kept inside the voxel, so castRay's start-cell rule takes the neighbour
// the DDA would have stepped to, and that neighbour's entry face is the hit normal. After
// kMaxCutoutContinuations cutouts the ray stops and reads as a miss (like the step cap).
#pragma once

#include "luxel/voxel/dda.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

inline constexpr int kMaxCutoutContinuations = 64;

struct SurfaceHit {
    Hit hit;                    // where the ray stops; hit.hit is false on a miss
    int slot = -1;              // texture slot of the hit voxel; -1: plain block (or a miss)
    Texel texel;                // the texel at the hit (white for plain blocks)
    int continuations = 0;      // cutout voxels the ray passed through
    bool cutoutCapped = false;  // stopped after kMaxCutoutContinuations (hit.hit is false)
};

// The ray that continues past `hit` (a voxel the ray entered) from where it leaves that voxel.
// Axes tied with the exit axis (edges, corners) start just inside their boundaries, ordered so
// the restarted traversal crosses them in the DDA's order (lower axis first).
Ray continueThroughVoxel(const Ray& ray, const Hit& hit);

// The first surface along the ray that is not a cutout. Voxels whose alpha selects a slot that
// `textures` lacks (or any voxel when textures is null) are plain blocks. hit.t is measured
// along the original ray (the continuations' t added up); surfaces past tMax are not met.
// `cast`, when given, is castRay(world, ray, tMax, stepCap) made already (castCameraRays gives
// it but for `steps`, docs/algorithms/voxel-traversal.md §4.6): the first cast is not made again.
SurfaceHit castToSurface(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                         int stepCap = 0, double tMax = kInfinity, const Hit* cast = nullptr);

}  // namespace luxel::voxel
