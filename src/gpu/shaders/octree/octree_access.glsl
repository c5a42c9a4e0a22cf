// The GPU side of the shared octree traversal (shared/octree_walk.h; the CPU side is
// src/octree/octree_access.h): the walk in float (voxel/walk_access.glsl) and the entry accessor
// over the `nodes[]` storage buffer the includer declares (and, for octreeLeafSrgb, `colours[]`
// and an OctreeRenderParams `params`).

#include "voxel/walk_access.glsl"

#define LUXEL_OCTREE uint

uint octreeEntry(uint tree, uint index) {
    return nodes[index];
}

#include "shared/octree_walk.h"

#ifdef LUXEL_OCTREE_WITH_COLOURS
vec3 octreeLeafSrgb(uint tree, uint entry) {
    if ((params.flags & LUXEL_OCTREE_COLOURS) == 0u) return vec3(0.8);
    const uint c = colours[entry];
    return vec3(float(c & 0xffu), float((c >> 8u) & 0xffu), float((c >> 16u) & 0xffu)) / 255.0;
}
#endif
