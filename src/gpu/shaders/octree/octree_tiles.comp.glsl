// One scale pass of the WebGL octree design's tile rendering, one invocation per pixel: the shared
// kernel (shared/octree_tiles.h; the CPU twin is octree::renderOctreeTiles,
// include/luxel/octree/octree_tiles.h). A frame is one dispatch per scale, coarse to fine; each
// reads the pixel states the previous one wrote, and the last (or any, for progressive frames)
// also shades the image.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/octree_tiles_layout.h"

layout(local_size_x = LUXEL_OCTREE_TILES_GROUP_X, local_size_y = LUXEL_OCTREE_TILES_GROUP_Y) in;
layout(std430, set = 0, binding = 0) readonly buffer Params { OctreeRenderParams params; };
layout(std430, set = 0, binding = 1) readonly buffer Nodes { uint nodes[]; };
layout(std430, set = 0, binding = 2) readonly buffer Colours { uint colours[]; };
layout(std430, set = 0, binding = 3) buffer States { OctreeTileState states[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Output { VoxelPixel pixels[]; };
layout(std430, set = 0, binding = 5) readonly buffer LeafCounts { uint leafCounts[]; };
layout(push_constant) uniform Push { OctreeTilesPush tiles; };

#define LUXEL_OCTREE_LEAF_ORDER_ON ((params.flags & LUXEL_OCTREE_LEAF_ORDER) != 0u)

// The tile passes shade surfaces only: the volume mode's light cache (shared/octree_light_cache.h)
// is never read here, and has no buffer.
float octreeLightCacheValue(uint tree, uint corner) {
    return 0.0;
}

#define LUXEL_OCTREE_WITH_COLOURS
#include "octree/octree_access.glsl"
#include "shared/octree_tiles.h"

void main() {
    const uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x >= params.width || pixel.y >= params.height) return;
    const uint i = pixel.y * params.width + pixel.x;
    vec3 o = vec3(0.0);
    vec3 d = vec3(0.0);
    octreePixelRay(params, int(pixel.x), int(pixel.y), o, d);
    const OctreeTileState s = octreeTilesPass(0u, params, o, d, states[i], tiles.pass,
                                              int(tiles.level), int(tiles.parentLevel));
    states[i] = s;
    if (tiles.shade != 0u) {
        const vec3 c = octreeTilesShade(0u, params, o, d, s, i);
        pixels[i] = VoxelPixel(c.x, c.y, c.z, 1.0);
    }
}
