// castRay: the shared traversal kernel (src/gpu/shaders/shared/voxel_dda.h, the same code the GPU
// runs) in double over a VoxelWorld; conventions in dda.h.
#include "luxel/voxel/dda.h"

#include <bit>
#include <cmath>

#include "luxel/core/parallel.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel {
namespace shared = gpu::shared;

Hit castRay(const VoxelWorld& world, const Ray& ray, double tMax, int stepCap, ChunkSkip skip) {
    const Int3 size = world.size();
    if (!finiteRay(ray) || !(tMax >= 0.0)) return Hit{};
    const int cap = stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    const shared::VoxelTrace trace = shared::voxelTraverse(
        world, {size.x, size.y, size.z}, chunkShift, toShared(ray.origin), toShared(ray.direction),
        tMax, cap, skip == ChunkSkip::Enabled, world.emptySpaceCurrent());
    return hitFromTrace(ray, trace);
}

std::vector<Hit> castRays(const VoxelWorld& world, std::span<const Ray> rays, double tMax,
                          int stepCap, ChunkSkip skip) {
    std::vector<Hit> hits(rays.size());
    parallelForRange(static_cast<int>(rays.size()), 1024, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) hits[i] = castRay(world, rays[i], tMax, stepCap, skip);
    });
    return hits;
}

}  // namespace luxel::voxel
