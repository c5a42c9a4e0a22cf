// castRay's walk for many rays on one thread, one ray per SIMD lane (cast_stream.cpp).
#pragma once

#include <span>

#include "luxel/voxel/dda.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel::stream {

// Which rays take SIMD lanes. The one-ray loop (fast::traverse) is faster for rays that start
// inside the world (secondary rays from surfaces, cameras inside the world: they begin with
// voxel steps in the start brick, which the one-ray loop takes with the mask in a register),
// the lanes for rays from outside (long runs of jumps after the slab clip)
// (docs/algorithms/voxel-traversal.md §4.2). Every ray in lanes: for the tests of the SIMD walk.
enum class Lanes { FromOutside, Every };

// Whether a ray's origin lies inside the world (such rays take the one-ray loop unless
// Lanes::Every).
inline bool startsInside(const VoxelWorld& world, const Ray& ray) {
    const Int3 size = world.size();
    const Vec3d& o = ray.origin;
    return o.x >= 0.0 && o.y >= 0.0 && o.z >= 0.0 && o.x < size.x && o.y < size.y && o.z < size.z;
}

struct Walk {
    const VoxelWorld* world;
    double tMax;
    int cap;  // the step cap, already resolved (> 0)
    Lanes lanes = Lanes::FromOutside;
};

// out[i] = the trace castRay makes of rays[i] with jumps (fast::traverseAny), for every ray.
void trace(const Walk& walk, std::span<const Ray> rays, gpu::shared::VoxelTrace* out);

}  // namespace luxel::voxel::stream
