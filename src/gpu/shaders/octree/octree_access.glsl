// The GPU side of the shared octree traversal (shared/octree_walk.h; the CPU side is
// src/octree/octree_access.h): the walk in float (voxel/walk_access.glsl) and the accessors over
// the `nodes[]` and `leafCounts[]` storage buffers the includer declares, with
// LUXEL_OCTREE_LEAF_ORDER_ON the expression saying whether colours are in leaf order (and, for
// octreeLeafSrgb, `colours[]` and an OctreeRenderParams `params`).

#include "voxel/walk_access.glsl"

#define LUXEL_OCTREE uint

uint octreeEntry(uint tree, uint index) {
    return nodes[index];
}

bool octreeLeafOrder(uint tree) {
    return LUXEL_OCTREE_LEAF_ORDER_ON;
}

uint octreeLeafCount(uint tree, uint octant) {
    return leafCounts[octant];
}

#include "shared/octree_walk.h"

#ifdef LUXEL_OCTREE_WITH_COLOURS
vec3 octreeLeafSrgb(uint tree, uint index) {
    if ((params.flags & LUXEL_OCTREE_COLOURS) == 0u) return vec3(0.8);
    const uint c = colours[index];
    return vec3(float(c & 0xffu), float((c >> 8u) & 0xffu), float((c >> 16u) & 0xffu)) / 255.0;
}
#endif
