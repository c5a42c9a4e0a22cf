// Exact ray casting through a sparse voxel octree: the first cell whose leaf is at least as opaque
// as a threshold, found by the shared traversal kernel (src/gpu/shaders/shared/octree_walk.h,
// the code the GPU runs) in double. Hits follow the conventions of the dense world's castRay
// (include/luxel/voxel/dda.h) and agree with it cell for cell on the equivalent dense grid.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "luxel/octree/octree.h"
#include "luxel/voxel/dda.h"

namespace luxel::octree {

struct TraceOptions {
    double tMax = voxel::kInfinity;
    int stepCap = 0;             // leaves visited; 0: 3 * (sx + sy + sz), more than any ray needs
    std::uint8_t threshold = 1;  // the least opacity that stops the ray (1: any non-empty leaf)
};

struct OctreeHit {
    voxel::Hit hit;
    std::uint32_t entry = 0;        // the hit leaf's entry; 0 on a miss
    std::uint32_t colourIndex = 0;  // its index in Octree::colours (Leaf::colourIndex); 0 on a miss
};

// `tree` must be valid (octree_validate.h).
OctreeHit castRay(const Octree& tree, const voxel::Ray& ray, const TraceOptions& options = {});

// castRay for every ray (in parallel): the CPU twin of the GPU octree cast pass.
std::vector<OctreeHit> castRays(const Octree& tree, std::span<const voxel::Ray> rays,
                                const TraceOptions& options = {});

}  // namespace luxel::octree
