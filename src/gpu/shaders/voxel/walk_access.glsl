// The GPU side of the shared A&W walk (shared/voxel_walk.h; the CPU side is
// src/voxel/walk_access.h): float precision, and the Hit the shading code reads, made from a
// finished walk. Included by the dense world's accessors (voxel_world_access.glsl) and the
// octree's (octree/octree_access.glsl).
#ifndef LUXEL_VOXEL_WALK_ACCESS_GLSL
#define LUXEL_VOXEL_WALK_ACCESS_GLSL

#define LUXEL_REAL float
#define LUXEL_REAL3 vec3

// Next float towards `toward` for the non-negative coordinates of the world box (a negative
// value is returned unchanged; the walk that uses it is bounded).
float voxelNextToward(float x, float toward) {
    if (toward < x) return x > 0.0 ? uintBitsToFloat(floatBitsToUint(x) - 1u) : x;
    return x >= 0.0 ? uintBitsToFloat(floatBitsToUint(x) + 1u) : x;
}

#include "shared/voxel_walk.h"

// A hit as the shading code reads it (dda.h's Hit in float).
struct Hit {
    bool hit;
    bool capped;
    ivec3 voxel;
    ivec3 normal;
    float t;
    vec3 point;
    float u, v;
    int steps;
};

Hit missHit() {
    return Hit(false, false, ivec3(0), ivec3(0), LUXEL_INFINITY, vec3(0.0), 0.0, 0.0, 0);
}

bool finite3(vec3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// The Hit of a finished walk (voxel::hitFromTrace on the CPU).
Hit hitFromTrace(vec3 o, vec3 d, VoxelTrace trace) {
    Hit h = missHit();
    h.steps = trace.steps;
    h.capped = trace.capped;
    if (!trace.hit) return h;
    h.hit = true;
    h.voxel = trace.cell;
    h.t = trace.t;
    if (trace.axis >= 0) h.normal[trace.axis] = -trace.stp[trace.axis];
    const VoxelSurface surface = voxelSurface(o, d, trace);
    h.point = surface.point;
    h.u = surface.u;
    h.v = surface.v;
    return h;
}

#endif
