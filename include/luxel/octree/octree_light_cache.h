// The light cache of the volume mode's scattering (docs/algorithms/sparse-voxel-octree.md §5,
// "Light cache"): the sun's transmittance traced exactly at the corners of a coarse grid over the
// content box, read back by trilinear interpolation instead of one shadow ray per sample. The
// per-corner arithmetic and the lookup are shared with the GPU pass
// (src/gpu/shaders/shared/octree_light_cache.h); fillLightCache is the CPU twin of
// OctreeGpu::lightCache.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"

namespace luxel::octree {

// The grid spacing (voxels) a render uses: `requested` when positive, 0 (no cache) for 0, and for
// kLightCacheAuto the smallest power of two giving at most kLightCacheAutoCells cells per axis.
int lightCacheStride(Int3 extent, int requested);

// T_sun at every corner for one tree and one light; valid while matches() holds, so callers that
// render many frames under the same light fill it once.
struct OctreeLightCache {
    int stride = 0;  // resolved; 0: empty
    Vec3 sun;        // unit direction toward the sun it was traced for
    float opacityScale = 0.0f;
    std::uint32_t windowLow = 0, windowHigh = 0;  // the opacity window it was traced for
    const std::uint32_t* nodes = nullptr;  // which tree (identity only: an edit needs clear())
    std::size_t nodeCount = 0;
    // The optical depth -ln T_sun per corner, in shared/octree_light_cache.h's order.
    std::vector<float> values;

    // Whether this cache holds what a render of `tree` with `options` reads.
    bool matches(const Octree& tree, const OctreeRenderOptions& options) const;
    void clear() { *this = OctreeLightCache{}; }
};

// Traces every corner (in parallel). Options without a cache (not volume scattering, or stride
// 0) give an empty cache; refuses, with the numbers, a grid larger than the memory.
Result<OctreeLightCache> fillLightCache(const Octree& tree, const OctreeRenderOptions& options);

}  // namespace luxel::octree
