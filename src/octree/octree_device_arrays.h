// A validated octree's arrays on the GPU, as every octree pass binds them: the entries, the
// colours packed one RGBA8 per uint (or one dummy word), and the leaf counts of a LeafOrder tree
// (or one dummy word). Shared by OctreeGpu and OctreeTilesGpu, so a tree is laid out one way.
#pragma once

#include <cstdint>
#include <memory>

#include "luxel/core/error.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree.h"

namespace luxel::octree {

struct OctreeDeviceArrays {
    std::shared_ptr<gpu::Buffer> nodes;
    std::shared_ptr<gpu::Buffer> colours;
    std::shared_ptr<gpu::Buffer> leafCounts;
    std::uint64_t bytes = 0;  // of the three buffers
    bool hasColours = false;
    bool leafOrder = false;
    Octree shape;  // depth and size only (no arrays): what renderParams reads
};

// The bytes the three buffers take, for a memory check before uploading.
std::uint64_t octreeDeviceBytes(const Octree& tree);

// Uploads; refuses, with the numbers, arrays (plus `extraBytes` the caller adds) larger than the
// device's memory.
Result<OctreeDeviceArrays> uploadOctreeArrays(gpu::Context& context, const Octree& tree,
                                              std::uint64_t extraBytes = 0);

}  // namespace luxel::octree
