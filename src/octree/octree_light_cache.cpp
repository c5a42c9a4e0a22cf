#include "luxel/octree/octree_light_cache.h"

#include <algorithm>
#include <string>

#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "octree/octree_access.h"
#include "octree/octree_render_params.h"

namespace luxel::octree {

namespace shared = gpu::shared;

int lightCacheStride(Int3 extent, int requested) {
    if (requested != kLightCacheAuto) return std::max(requested, 0);
    const int longest = std::max({extent.x, extent.y, extent.z});
    int stride = 1;
    while ((longest + stride - 1) / stride > kLightCacheAutoCells) stride *= 2;
    return stride;
}

bool OctreeLightCache::matches(const Octree& tree, const OctreeRenderOptions& options) const {
    const shared::OctreeRenderParams p = mediumParams(tree, options);
    return stride == static_cast<int>(p.lightStride) && nodes == tree.nodes.data() &&
           nodeCount == tree.nodes.size() && sun.x == p.sunX && sun.y == p.sunY &&
           sun.z == p.sunZ && opacityScale == p.opacityScale && windowLow == p.windowLow &&
           windowHigh == p.windowHigh;
}

Status checkLightCacheSize(const shared::OctreeRenderParams& p) {
    const shared::uvec3 c = shared::octreeLightCacheCells(p);
    const std::uint64_t corners = std::uint64_t{c.x + 1} * (c.y + 1) * (c.z + 1);
    if (corners > (std::uint64_t{1} << 31)) {
        return Error("octree light cache: " + std::to_string(corners) +
                     " corners is more than 2^31; use a larger light_cache_stride");
    }
    return checkMemory(corners * sizeof(float), "an octree light cache");
}

Result<OctreeLightCache> fillLightCache(const Octree& tree, const OctreeRenderOptions& options) {
    if (Status s = validateRenderOptions(options); !s) return s.error();
    const shared::OctreeRenderParams p = mediumParams(tree, options);
    OctreeLightCache cache;
    if (p.lightStride == 0) return cache;
    if (Status s = checkLightCacheSize(p); !s) return s.error();
    cache.stride = static_cast<int>(p.lightStride);
    cache.sun = Vec3(p.sunX, p.sunY, p.sunZ);
    cache.opacityScale = p.opacityScale;
    cache.windowLow = p.windowLow;
    cache.windowHigh = p.windowHigh;
    cache.nodes = tree.nodes.data();
    cache.nodeCount = tree.nodes.size();
    cache.values.resize(shared::octreeLightCacheCorners(p));
    const OctreeArrays arrays = arraysOf(tree);
    const int corners = static_cast<int>(cache.values.size());
    parallelForRange(corners, 256, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            cache.values[i] = shared::octreeLightCacheCorner(arrays, p, static_cast<uint>(i));
        }
    });
    return cache;
}

}  // namespace luxel::octree
