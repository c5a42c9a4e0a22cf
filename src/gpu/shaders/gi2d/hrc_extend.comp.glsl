// HRC ray extension (paper Eq 18-20; CPU reference: src/gi2d/hrc/ray_tables.cpp extendLevels):
// T_n(p, y, k) = average of over(T_{n-1}(2p, y, lo), T_{n-1}(2p+1, y + dy(lo), hi)) and the same with
// lo and hi swapped; lo = k >> 1, hi = (k + 1) >> 1. One invocation per (row, ray, plane).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"

layout(local_size_x = LUXEL_HRC_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Below { uint below[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Above { uint above[]; };
layout(push_constant) uniform Push { HrcExtendParams params; };

struct Interval {
    vec3 radiance;
    vec3 transmittance;
};

// Outside the frame: empty space.
Interval loadBelow(int p, int y, int k) {
    if (p < 0 || p >= int(params.planesBelow) || y < 0 || y >= int(params.rows)) {
        return Interval(vec3(0.0), vec3(1.0));
    }
    const uint rays = (1u << (params.level - 1u)) + 1u;
    const uint entry = (uint(p) * rays + uint(k)) * params.rows + uint(y);
    const uint word = entry * LUXEL_HRC_ENTRY_WORDS;
    const vec2 a = unpackHalf2x16(below[word]);
    const vec2 b = unpackHalf2x16(below[word + 1u]);
    const vec2 c = unpackHalf2x16(below[word + 2u]);
    return Interval(vec3(a.x, a.y, b.x), vec3(b.y, c.x, c.y));
}

Interval over(Interval near, Interval far) {
    return Interval(near.radiance + near.transmittance * far.radiance,
                    near.transmittance * far.transmittance);
}

void main() {
    const uint y = gl_GlobalInvocationID.x, k = gl_GlobalInvocationID.y;
    const uint p = gl_GlobalInvocationID.z;
    if (y >= params.rows || p >= params.planes) return;
    const int h = 1 << (params.level - 1u);
    const int lo = int(k) >> 1, hi = (int(k) + 1) >> 1;
    const int iy = int(y), ip = int(p);
    Interval v = over(loadBelow(2 * ip, iy, lo), loadBelow(2 * ip + 1, iy + 2 * lo - h, hi));
    if (lo != hi) {  // odd k: average the two bent paths
        const Interval b =
            over(loadBelow(2 * ip, iy, hi), loadBelow(2 * ip + 1, iy + 2 * hi - h, lo));
        v.radiance = (v.radiance + b.radiance) * 0.5;
        v.transmittance = (v.transmittance + b.transmittance) * 0.5;
    }
    const uint rays = (1u << params.level) + 1u;
    const uint word = ((p * rays + k) * params.rows + y) * LUXEL_HRC_ENTRY_WORDS;
    above[word] = packHalf2x16(v.radiance.xy);
    above[word + 1u] = packHalf2x16(vec2(v.radiance.z, v.transmittance.x));
    above[word + 2u] = packHalf2x16(v.transmittance.yz);
}
