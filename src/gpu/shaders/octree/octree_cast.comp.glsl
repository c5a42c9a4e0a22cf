// A batch of rays through the octree, one invocation per ray: the exact traversal every GPU
// octree pass runs, as a pass of its own so it can be compared ray by ray with the CPU twin
// (octree::castRays, include/luxel/octree/octree_trace.h).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/octree_layout.h"

layout(local_size_x = LUXEL_OCTREE_CAST_GROUP) in;
layout(std430, set = 0, binding = 0) readonly buffer Nodes { uint nodes[]; };
layout(std430, set = 0, binding = 1) readonly buffer Rays { VoxelCastRay rays[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Hits { VoxelCastHit hits[]; };
layout(std430, set = 0, binding = 3) readonly buffer LeafCounts { uint leafCounts[]; };
layout(push_constant) uniform Push { OctreeCastPush batch; };

#define LUXEL_OCTREE_LEAF_ORDER_ON ((batch.flags & LUXEL_OCTREE_LEAF_ORDER) != 0u)
#include "octree/octree_access.glsl"

void main() {
    const uint i = LUXEL_LINEAR_INVOCATION;
    if (i >= batch.rays) return;
    const VoxelCastRay r = rays[i];
    const vec3 o = vec3(r.originX, r.originY, r.originZ);
    const vec3 d = vec3(r.directionX, r.directionY, r.directionZ);
    Hit h = missHit();
    uint entry = 0u;
    uint colourIndex = 0u;
    if (finite3(o) && finite3(d) && !(d.x == 0.0 && d.y == 0.0 && d.z == 0.0) && r.tMax >= 0.0) {
        const ivec3 size = ivec3(batch.sizeX, batch.sizeY, batch.sizeZ);
        const VoxelTrace trace =
            octreeTraverseLeaf(0u, int(batch.depth), size, o, d, r.tMax, int(batch.stepCap),
                               batch.threshold, entry, colourIndex);
        h = hitFromTrace(o, d, trace);
    }
    hits[i] = VoxelCastHit((h.hit ? 1u : 0u) | (h.capped ? 2u : 0u), h.steps, h.voxel.x, h.voxel.y,
                           h.voxel.z, h.normal.x, h.normal.y, h.normal.z, h.t, h.point.x,
                           h.point.y, h.point.z, h.u, h.v, entry, colourIndex);
}
