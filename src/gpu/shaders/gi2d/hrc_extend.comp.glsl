// HRC ray extension (paper Eq 18-20; CPU twin: extendLevel in src/gi2d/hrc/ray_tables.cpp):
// T_n(p, y, k) = average of hrcOver(T_{n-1}(2p, y, lo), T_{n-1}(2p+1, y + dy(lo), hi)) and the same with
// lo and hi swapped; lo = k >> 1, hi = (k + 1) >> 1. One invocation per (row, ray, plane).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"
#include "gi2d/hrc_common.glsl"

layout(local_size_x = LUXEL_HRC_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Below { HrcTableEntry below[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Above { HrcTableEntry above[]; };
layout(push_constant) uniform Push { HrcExtendParams params; };

// Outside the frame: empty space.
HrcInterval loadBelow(int p, int y, int k) {
    if (p < 0 || p >= int(params.planesBelow) || y < 0 || y >= int(params.rows)) {
        return hrcEmptyInterval();
    }
    return unpackEntry(below[tableIndex(params.level - 1u, uint(p), uint(k), uint(y), params.rows)]);
}

void main() {
    const uint y = gl_GlobalInvocationID.x, k = gl_GlobalInvocationID.y;
    const uint p = gl_GlobalInvocationID.z;
    if (y >= params.rows || p >= params.planes) return;
    const int below = int(params.level) - 1;
    const int lo = int(k) >> 1, hi = (int(k) + 1) >> 1;
    const int iy = int(y), ip = int(p);
    HrcInterval v = hrcOver(loadBelow(2 * ip, iy, lo), loadBelow(2 * ip + 1, iy + hrcRayOffsetY(below, lo), hi));
    if (lo != hi) {  // odd k: average the two bent paths
        const HrcInterval b =
            hrcOver(loadBelow(2 * ip, iy, hi), loadBelow(2 * ip + 1, iy + hrcRayOffsetY(below, hi), lo));
        v = hrcAverage(v, b);
    }
    above[tableIndex(params.level, p, k, y, params.rows)] = packEntry(v);
}
