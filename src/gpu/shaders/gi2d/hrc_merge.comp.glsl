// HRC cone merge (docs/algorithms/holographic-radiance-cascades.md §5, paper Eq 13-17; CPU reference: mergeCascade in
// src/gi2d/hrc/cone_merge.cpp). One invocation per (pair of rows, cone, plane): the cones are stored as binary16, two
// rows per 32-bit word (shared/hrc_layout.h), so each invocation writes whole words.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"
#include "gi2d/hrc_common.glsl"

layout(local_size_x = LUXEL_HRC_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Table { HrcTableEntry table[]; };
layout(std430, set = 0, binding = 1) readonly buffer Upper { HrcConePair upper[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Cones { HrcConePair cones[]; };
layout(std430, set = 0, binding = 3) readonly buffer Weights { float weight[]; };
layout(std430, set = 0, binding = 4) readonly buffer NearLights { uint nearLightWords[]; };
layout(push_constant) uniform Push { HrcMergeParams params; };

HrcInterval tableAt(int p, int y, int k) {
    if (p < 0 || p >= int(params.planes) || y < 0 || y >= int(params.rows)) {
        return hrcEmptyInterval();
    }
    return unpackEntry(table[tableIndex(params.level, uint(p), uint(k), uint(y), params.rows)]);
}

// Cone j of the upper cascade at (p, y); outside the frame (or above the top) the sky.
vec3 upperAt(int p, int y, int j) {
    if (params.hasUpper == 0u || p < 0 || p >= int(params.upperPlanes) || y < 0 ||
        y >= int(params.rows)) {
        return vec3(params.skyR, params.skyG, params.skyB) * weight[j];
    }
    const uint upperCones = 1u << (params.level + 1u);
    const uint r = hrcConeHalf(uint(p), upperCones, uint(j), 0u, uint(y), params.rows);
    const uint stride = hrcConeRowHalves(params.rows);
    return vec3(halfOfWord(upper[r >> 1].evenOddRows, r),
                halfOfWord(upper[(r + stride) >> 1].evenOddRows, r),
                halfOfWord(upper[(r + 2u * stride) >> 1].evenOddRows, r));
}

// The near probe's row weight (§5.1) at plane p, row y: at cascade 0 weighed by the near-light
// mask at the pixel the plane is read out for, p - 1 (§6.2, §12.3; plane 0 reaches no pixel).
float nearRowWeight(int p, int y) {
    if (params.level != 0u || params.nearLights == 0u || p < 1) {
        return hrcNearRowWeight(int(params.level));
    }
    const ivec2 c = hrcFrameToCanvas(params.frustum, ivec2(p - 1, y), int(params.canvasWidth),
                                     int(params.canvasHeight));
    const uint b = uint(c.y) * params.canvasWidth + uint(c.x);
    return hrcNearRowWeightAt(0, (nearLightWords[b >> 2] >> (8u * (b & 3u))) & 0xffu);
}

// R_level(p, y, i): the sum over the cone's two rays.
vec3 mergeAt(int ip, int iy, uint i) {
    // The rows each upper read blends (§5.1).
    const float second = hrcSecondRowWeight(int(params.level));
    const float nearSecond = (ip & 1) == 1 ? 0.0 : nearRowWeight(ip, iy);
    vec3 sum = vec3(0.0);
    for (int s = 0; s < 2; ++s) {
        const int k = int(i) + s, j = 2 * int(i) + s;
        const int dy = hrcRayOffsetY(int(params.level), k);
        const int axis = hrcTowardsAxis(s);
        const float w = weight[j];
        if ((ip & 1) == 1) {  // the ray ends on upper plane (p + 1) / 2 (Eq 14)
            const int q = (ip + 1) / 2, e = iy + dy;
            sum += hrcMergeOdd(tableAt(ip, iy, k), w,
                               hrcBlendTwoRows(upperAt(q, e, j), upperAt(q, e + axis, j), second));
        } else {  // near and far merged, then averaged (Eq 15-17)
            const int q = ip / 2, e = iy + 2 * dy;
            const vec3 nearRead =
                nearSecond == 0.0
                    ? upperAt(q, iy, j)
                    : hrcBlendTwoRows(upperAt(q, iy, j), upperAt(q, iy + dy, j), nearSecond);
            const vec3 farRead = hrcBlendThreeRows(
                upperAt(q + 1, e, j), upperAt(q + 1, e + axis, j), upperAt(q + 1, e + 2 * axis, j),
                second);
            sum += hrcMergeEven(nearRead, hrcOver(tableAt(ip, iy, k), tableAt(ip + 1, iy + dy, k)),
                                w, farRead);
        }
    }
    return sum;
}

void main() {
    const uint y = 2u * gl_GlobalInvocationID.x, i = gl_GlobalInvocationID.y;
    const uint p = gl_GlobalInvocationID.z;
    if (y >= params.rows || p >= params.planes) return;
    const vec3 first = mergeAt(int(p), int(y), i);
    // The padding row of an odd row count stores zero.
    const vec3 second = y + 1u < params.rows ? mergeAt(int(p), int(y) + 1, i) : vec3(0.0);
    const uint out0 = hrcConeHalf(p, 1u << params.level, i, 0u, y, params.rows) >> 1;
    const uint stride = hrcConeRowHalves(params.rows) >> 1;
    cones[out0].evenOddRows = packHalf2x16(vec2(first.x, second.x));
    cones[out0 + stride].evenOddRows = packHalf2x16(vec2(first.y, second.y));
    cones[out0 + 2u * stride].evenOddRows = packHalf2x16(vec2(first.z, second.z));
}
