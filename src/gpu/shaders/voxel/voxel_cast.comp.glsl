// A batch of rays through the voxel world, one invocation per ray: the traversal every GPU voxel
// pass runs, as a pass of its own so it can be compared ray by ray with the CPU twin (castRays in
// include/luxel/voxel/dda.h).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_layout.h"

layout(local_size_x = LUXEL_VOXEL_CAST_GROUP) in;
layout(std430, set = 0, binding = 0) readonly buffer Params { VoxelRenderParams params; };
layout(std430, set = 0, binding = 1) readonly buffer Voxels { uint voxels[]; };
layout(std430, set = 0, binding = 2) readonly buffer ChunkSolid { uint chunkSolid[]; };
layout(std430, set = 0, binding = 3) readonly buffer Rays { VoxelCastRay rays[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Hits { VoxelCastHit hits[]; };
layout(std430, set = 0, binding = 5) readonly buffer BrickMasks { uvec2 brickMasks[]; };
layout(std430, set = 0, binding = 6) readonly buffer BrickReach { uint brickReach[]; };
layout(push_constant) uniform Push { VoxelCastPush batch; };

#include "voxel/voxel_world_access.glsl"

void main() {
    const uint i = LUXEL_LINEAR_INVOCATION;
    if (i >= batch.rays) return;
    const VoxelCastRay r = rays[i];
    const Hit h = castRayLimited(vec3(r.originX, r.originY, r.originZ),
                                 vec3(r.directionX, r.directionY, r.directionZ), r.tMax,
                                 int(batch.stepCap), r.jumps != 0u);
    hits[i] = VoxelCastHit((h.hit ? 1u : 0u) | (h.capped ? 2u : 0u), h.steps, h.voxel.x, h.voxel.y,
                           h.voxel.z, h.normal.x, h.normal.y, h.normal.z, h.t, h.point.x,
                           h.point.y, h.point.z, h.u, h.v, 0u, 0u);
}
