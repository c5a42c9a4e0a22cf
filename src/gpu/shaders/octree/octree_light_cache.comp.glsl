// Fills the light cache of the volume mode, one invocation per corner: T_sun traced exactly from
// each corner (shared/octree_render.h's octreeLightCacheCorner; the CPU twin is
// octree::fillLightCache, include/luxel/octree/octree_light_cache.h).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/octree_layout.h"

layout(local_size_x = LUXEL_OCTREE_LIGHT_CACHE_GROUP) in;
layout(std430, set = 0, binding = 0) readonly buffer Params { OctreeRenderParams params; };
layout(std430, set = 0, binding = 1) readonly buffer Nodes { uint nodes[]; };
layout(std430, set = 0, binding = 2) readonly buffer LeafCounts { uint leafCounts[]; };
layout(std430, set = 0, binding = 3) buffer LightCache { float lightCache[]; };

#define LUXEL_OCTREE_LEAF_ORDER_ON ((params.flags & LUXEL_OCTREE_LEAF_ORDER) != 0u)
#include "octree/octree_access.glsl"

// octree_render.h's colour and cache accessors, unused by the corner trace.
vec3 octreeLeafSrgb(uint tree, uint index) {
    return vec3(0.8);
}

float octreeLightCacheValue(uint tree, uint corner) {
    return lightCache[corner];
}

#include "shared/octree_render.h"

void main() {
    const uint corner = LUXEL_LINEAR_INVOCATION;
    if (corner >= octreeLightCacheCorners(params)) return;
    lightCache[corner] = octreeLightCacheCorner(0u, params, corner);
}
