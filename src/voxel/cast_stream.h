// castRay's walk for many rays on one thread, one ray per SIMD lane (cast_stream.cpp).
#pragma once

#include <span>

#include "luxel/voxel/dda.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel::stream {

struct Walk {
    const VoxelWorld* world;
    double tMax;
    int cap;  // the step cap, already resolved (> 0)
};

// out[i] = the trace castRay makes of rays[i] with jumps (fast::traverseAny), for every ray.
void trace(const Walk& walk, std::span<const Ray> rays, gpu::shared::VoxelTrace* out);

}  // namespace luxel::voxel::stream
