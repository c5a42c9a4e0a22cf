// castRay over an octree: the shared kernel (octree_walk.h) in double; conventions in dda.h.
#include "luxel/octree/octree_trace.h"

#include "luxel/core/parallel.h"
#include "octree/octree_access.h"

namespace luxel::octree {

namespace shared = gpu::shared;

OctreeHit castRay(const Octree& tree, const voxel::Ray& ray, const TraceOptions& options) {
    if (!voxel::finiteRay(ray) || !(options.tMax >= 0.0)) return {};
    const Int3 size = tree.extent();
    const int cap = options.stepCap > 0 ? options.stepCap : 3 * (size.x + size.y + size.z);
    shared::uint entry = 0, colourIndex = 0;
    const shared::VoxelTrace trace = shared::octreeTraverseLeaf(
        arraysOf(tree), tree.depth, {size.x, size.y, size.z}, voxel::toShared(ray.origin),
        voxel::toShared(ray.direction), options.tMax, cap,
        std::max<shared::uint>(options.threshold, 1), entry, colourIndex);
    return {voxel::hitFromTrace(ray, trace), entry, colourIndex};
}

std::vector<OctreeHit> castRays(const Octree& tree, std::span<const voxel::Ray> rays,
                                const TraceOptions& options) {
    std::vector<OctreeHit> hits(rays.size());
    parallelForRange(static_cast<int>(rays.size()), 1024, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) hits[i] = castRay(tree, rays[i], options);
    });
    return hits;
}

}  // namespace luxel::octree
