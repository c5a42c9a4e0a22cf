// The SIMD walk behind castRayBatch and occludedBatch (src/voxel/cast_stream.cpp) with every ray
// in a lane. The batch calls give rays that start inside the world the one-ray loop instead
// (docs/algorithms/voxel-traversal.md §4.2); the tests run the lanes on those rays too, so both
// loops stay checked against castRay and the shared kernel.
#pragma once

#include <span>
#include <vector>

#include "luxel/voxel/dda.h"
#include "voxel/cast_stream.h"
#include "voxel/walk_access.h"

namespace luxel::voxel {

inline std::vector<Hit> castRayLanes(const VoxelWorld& world, std::span<const Ray> rays,
                                     double tMax, int stepCap) {
    const Int3 size = world.size();
    const int cap = stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);
    std::vector<gpu::shared::VoxelTrace> traces(rays.size());
    stream::trace({&world, tMax, cap, stream::Lanes::Every}, rays, traces.data());
    std::vector<Hit> hits(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = hitFromTrace(rays[i], traces[i]);
    return hits;
}

}  // namespace luxel::voxel
