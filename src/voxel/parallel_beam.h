// Occlusion rays that share one direction (shadow rays towards the sun from neighbouring surface
// points): a run of them with nearby origins is a beam of parallel rays, and one walk of the
// beam's slabs from the world's far side finds a plane past which none of them meets a solid
// voxel, so each ray's exact walk ends there (docs/algorithms/voxel-traversal.md §4.7).
#pragma once

#include <cstddef>
#include <span>

#include "luxel/voxel/dda.h"

namespace luxel::voxel::stream {

// Rays of one beam: at most kBeamRays, their origins within kBeamWidth voxels of each other across
// the main axis (measured along the direction, so origins on one ray count as one point).
inline constexpr std::size_t kBeamRays = 64;
inline constexpr double kBeamWidth = 10.0;
// Shorter runs take the plain walk: the beam's own walk costs about as much as a few rays'.
inline constexpr std::size_t kMinBeamRays = 8;

// The plane `axis` = `plane` (a cell boundary) past which no ray of the beam meets a solid
// voxel: every cell any of them visits beyond it is empty.
struct BeamLimit {
    int axis = -1;
    int plane = 0;
};

// How many rays from the front of `rays` form one beam: the first is finite with a direction
// fast::eligible takes, the others have its direction exactly and finite origins within
// kBeamWidth of the others' across the main axis. 0 where the first ray does not qualify.
std::size_t beamLength(const VoxelWorld& world, std::span<const Ray> rays);

// The planes of beams in one world.
class BeamScan {
  public:
    explicit BeamScan(const VoxelWorld& world);

    // The beam's plane: its slabs across the main axis, from the world's furthest chunk slab that
    // holds a solid voxel back towards the origins, chunk slabs, then brick slabs, then cell
    // slabs; the far face of the first that may hold a solid voxel in the rays' box (the near face
    // of the furthest-back origin's cell slab when none does). `beam` is a run beamLength accepted.
    BeamLimit limit(std::span<const Ray> beam);

  private:
    static constexpr int kUnknown = -2;
    // The furthest chunk slab along axis m in direction sgn that holds a solid voxel (-1 or the
    // slab count when none does), found on first use.
    int farChunk(int m, int sgn);

    const VoxelWorld& world_;
    int farChunk_[3][2];
};

// The t at which `ray` crosses the beam's plane: the walk's own boundary formula,
// (plane - o_m) * (1 / d_m), so a walk with this tMax visits exactly the cells before the plane.
inline double beamPlaneT(const Ray& ray, BeamLimit limit) {
    const int m = limit.axis;
    return (static_cast<double>(limit.plane) - ray.origin[m]) * (1.0 / ray.direction[m]);
}

}  // namespace luxel::voxel::stream
