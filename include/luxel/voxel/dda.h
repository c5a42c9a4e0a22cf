// Exact Amanatides & Woo (1987) voxel traversal over a VoxelWorld, with jumps over empty chunks
// and empty 4^3 bricks.
//
// Conventions and edge-case decisions (see docs/algorithms/voxel-traversal.md §2.2):
// - The ray is P(t) = origin + t * direction; the direction need not be unit length, and t is in
//   units of its length. Rays with a NaN/inf component or a zero direction never hit.
// - The ray is first clipped to the world box [0, size] with a slab test. A direction component
//   that is +0.0 or -0.0 is treated identically: no division, that axis never steps (its next
//   boundary is at t = +inf), and the ray only meets the world if origin[a] lies in [0, size[a]).
// - Start cell (at t0 = max(t_enter, 0)): floor of the point, except that a coordinate lying
//   exactly on a cell boundary while the ray moves towards -inf on that axis takes the lower cell
//   (the ray immediately goes there; this avoids zero-length visits and self-hits of secondary rays
//   started on a face). Clamped into the world, since the entry point may round outside.
// - The boundary t of the next cell on each axis is recomputed from the integer cell index,
//   t = (cell + (step > 0) - origin) / direction, every time that axis steps: no accumulated drift
//   however long the ray, and bit-identical values for the same cell however it was reached.
// - Ties (the ray crosses an edge or a corner): the axis with the lowest index (x, then y, then z)
//   steps first, so the traversal is 6-connected and never leaks through a 1-voxel diagonal wall.
//   A neighbour touched only along the edge is visited and can be hit (at the edge's t).
// - Hits: t is the entry t of the hit voxel, normal = -step on the axis crossed to enter it. For
// the
//   first voxel the normal is the face through which the ray entered the world box (ties: the
//   highest tied axis, matching the step order above), or, for an origin inside the world, the
//   face the origin lies on when it is exactly on the boundary the ray enters through. An origin
//   strictly inside a solid voxel gives hit at t = 0 with normal (0, 0, 0).
// - A hit is reported only when its t <= tMax. The step cap counts loop iterations (voxel visits
//   and block jumps); reaching it returns hit = false, capped = true, steps == cap.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Ray {
    Vec3d origin;
    Vec3d direction;
};

struct Hit {
    bool hit = false;
    bool capped = false;   // the step cap ended the traversal (hit is false)
    Int3 voxel;            // the hit voxel (zero on a miss)
    Int3 normal;           // axis-aligned face normal towards the ray's origin side; see above
    double t = kInfinity;  // entry t of the hit voxel; +inf on a miss
    Vec3d point;           // origin + t * direction, snapped onto the hit face's plane
    float u = 0,
          v = 0;    // position on the hit face in [0, 1) (the Unity tracer's mapping, see dda.cpp)
    int steps = 0;  // loop iterations: voxel visits plus block jumps
};

// Whether castRay jumps over empty space: with the world's brick reach current
// (VoxelWorld::emptySpaceCurrent) over the largest empty cube of bricks from an empty brick
// towards the ray's direction octant (VoxelWorld::brickReach), else
// over an empty chunk (chunkSolidCount == 0) or an empty brick (brickMask == 0); voxels are tested
// through the brick masks. Both settings give the same result except for `steps` (and hence the
// step cap).
enum class ChunkSkip { Enabled, Disabled };

// First solid voxel along the ray with entry t in [0, tMax]. stepCap 0 means 3 * (sx + sy + sz),
// more than any traversal of the world needs (at most sx + sy + sz - 2 cells).
Hit castRay(const VoxelWorld& world, const Ray& ray, double tMax = kInfinity, int stepCap = 0,
            ChunkSkip skip = ChunkSkip::Enabled);

// castRay's `hit` alone (an occlusion test, e.g. a shadow ray): the walk stops at the first solid
// voxel and skips the hit's point and face coordinates.
bool occluded(const VoxelWorld& world, const Ray& ray, double tMax = kInfinity, int stepCap = 0);

// castRay and occluded for many rays on the calling thread, several at a time (one ray per SIMD
// lane, coherent or not): hits[i] == castRay(world, rays[i], tMax, stepCap) field by field, steps
// included, and occluded[i] == occluded(world, rays[i], tMax, stepCap). The spans have equal sizes.
// occludedBatch walks a run of rays with one direction and nearby origins (shadow rays towards the
// sun from neighbouring points) as one beam, each ray only up to a plane past which none of them
// meets a solid voxel (docs/algorithms/voxel-traversal.md §4.7): rays in such runs are cheaper.
void castRayBatch(const VoxelWorld& world, std::span<const Ray> rays, std::span<Hit> hits,
                  double tMax = kInfinity, int stepCap = 0);
void occludedBatch(const VoxelWorld& world, std::span<const Ray> rays,
                   std::span<std::uint8_t> occluded, double tMax = kInfinity, int stepCap = 0);

// castRayBatch for camera rays: rays from one origin, in tiles of kCameraTileRays consecutive
// rays (a run of an image row, or a square of pixels), each tile a thin frustum. Where the
// origin lies outside the world, each tile's frustum is walked once to a plane before which none
// of its rays meets a solid voxel (from outside, each 16 rays of a tile walk on to a plane of
// their own), and each ray's walk begins with one jump to that plane
// (docs/algorithms/voxel-traversal.md §4.6). hits[i] equals castRay(world, rays[i], tMax,
// stepCap) field by field except `steps`, which counts the iterations this walk makes (the jump
// to the plane is one; the frustum walk is not counted; a ray of a frustum with no solid voxel
// counts that one jump out of the world where it enters it, 0 where it does not); rays of tiles
// without a plane keep castRay's steps. Every ray takes castRay's one-ray loop (from outside, the
// rays of 16 start and jump to their plane together in SIMD lanes first, §4.6 "Starts in lanes");
// with a step cap below the world's sx + sy + sz, or the brick reach stale, this is castRayBatch.
inline constexpr std::size_t kCameraTileRays = 64;
void castCameraRays(const VoxelWorld& world, std::span<const Ray> rays, std::span<Hit> hits,
                    double tMax = kInfinity, int stepCap = 0);

// castRay run by the shared kernel (src/gpu/shaders/shared/voxel_dda.h) as written, in double:
// the reference the CPU's own loop is tested against (castRay gives the same Hit, steps included).
Hit castRayShared(const VoxelWorld& world, const Ray& ray, double tMax = kInfinity, int stepCap = 0,
                  ChunkSkip skip = ChunkSkip::Enabled);

// castRay for every ray (in parallel): the CPU twin of VoxelGpuRenderer::castRays.
std::vector<Hit> castRays(const VoxelWorld& world, std::span<const Ray> rays,
                          double tMax = kInfinity, int stepCap = 0,
                          ChunkSkip skip = ChunkSkip::Enabled);

}  // namespace luxel::voxel
