// The CPU side of the shared octree kernels (src/gpu/shaders/shared/octree_walk.h and
// octree_render.h): the walk in double (voxel/walk_access.h) and the accessors over the arrays.
// The GPU side is src/gpu/shaders/octree/octree_access.glsl.
#pragma once

#include <cstdint>

#include "luxel/octree/octree.h"
#include "voxel/walk_access.h"

namespace luxel::octree {

// The arrays the kernels read: the entries and, when present, the colours (per entry, or in leaf
// order with the per-octant leaf counts).
struct OctreeArrays {
    const std::uint32_t* nodes = nullptr;
    const Colour* colours = nullptr;
    const std::uint32_t* leafCounts = nullptr;  // LeafOrder trees only
    const float* lightCache = nullptr;          // T_sun per light cache corner, when cached
};

inline OctreeArrays arraysOf(const Octree& tree) {
    return {tree.nodes.data(), tree.hasColours() ? tree.colours.data() : nullptr,
            tree.leafOrder() ? tree.leafCounts.data() : nullptr};
}

}  // namespace luxel::octree

#define LUXEL_OCTREE const ::luxel::octree::OctreeArrays&

namespace luxel::gpu::shared {

inline uint octreeEntry(const octree::OctreeArrays& tree, uint index) {
    return tree.nodes[index];
}

inline bool octreeLeafOrder(const octree::OctreeArrays& tree) {
    return tree.leafCounts != nullptr;
}

inline uint octreeLeafCount(const octree::OctreeArrays& tree, uint octant) {
    return tree.leafCounts[octant];
}

inline float octreeLightCacheValue(const octree::OctreeArrays& tree, uint corner) {
    return tree.lightCache[corner];
}

inline vec3 octreeLeafSrgb(const octree::OctreeArrays& tree, uint index) {
    if (!tree.colours) return vec3(0.8f);
    const octree::Colour c = tree.colours[index];
    return vec3(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f);
}

}  // namespace luxel::gpu::shared

#include "gpu/shaders/shared/octree_render.h"
#include "gpu/shaders/shared/octree_walk.h"
