// Renders an octree, one invocation per pixel: the shared pixel kernel (shared/octree_render.h;
// the CPU twin is octree::renderOctree, include/luxel/octree/octree_render.h).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/octree_layout.h"

layout(local_size_x = LUXEL_OCTREE_RENDER_GROUP_X, local_size_y = LUXEL_OCTREE_RENDER_GROUP_Y) in;
layout(std430, set = 0, binding = 0) readonly buffer Params { OctreeRenderParams params; };
layout(std430, set = 0, binding = 1) readonly buffer Nodes { uint nodes[]; };
layout(std430, set = 0, binding = 2) readonly buffer Colours { uint colours[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Output { VoxelPixel pixels[]; };
layout(std430, set = 0, binding = 4) readonly buffer LeafCounts { uint leafCounts[]; };
layout(std430, set = 0, binding = 5) readonly buffer LightCache { float lightCache[]; };

#define LUXEL_OCTREE_LEAF_ORDER_ON ((params.flags & LUXEL_OCTREE_LEAF_ORDER) != 0u)
#define LUXEL_OCTREE_WITH_COLOURS
#include "octree/octree_access.glsl"

float octreeLightCacheValue(uint tree, uint corner) {
    return lightCache[corner];
}

#include "shared/octree_render.h"

void main() {
    const uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x >= params.width || pixel.y >= params.height) return;
    const vec3 c = octreeRenderPixel(0u, params, int(pixel.x), int(pixel.y));
    pixels[pixel.y * params.width + pixel.x] = VoxelPixel(c.x, c.y, c.z, 1.0);
}
