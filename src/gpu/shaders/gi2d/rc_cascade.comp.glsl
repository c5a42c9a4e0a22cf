// Vanilla Radiance Cascades, one cascade (CPU twin: cascadePass in src/gi2d/rc/rc_cascade_pass.h):
// every probe traces its directions' intervals through the medium with an exact DDA, merges what
// lies beyond (bilinear over the 4 upper probes, or the bilinear fix), and stores the mean of each
// group of 4 directions (pre-averaging). One invocation per (probe, stored value).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/medium_layout.h"
#include "shared/rc_layout.h"
#define LUXEL_REAL float
#define LUXEL_REAL2 vec2
#include "shared/rc_kernels.h"

layout(local_size_x = LUXEL_RC_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { MediumTexel medium[]; };
layout(std430, set = 0, binding = 1) readonly buffer Upper { RgbTexel upper[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Current { RgbTexel current[]; };
layout(push_constant) uniform Push { RcCascadeParams params; };

// The cascade marches the canvas itself, row by row.
uint mediumIndex(ivec2 cell, uint width) {
    return uint(cell.y) * width + uint(cell.x);
}

#include "gi2d/march2d.glsl"

struct Segment {
    vec3 radiance;
    vec3 transmittance;
    bool leaves;  // the end lies outside the canvas: open space beyond
};

bool outside(vec2 p) {
    return p.x < 0.0 || p.y < 0.0 || p.x > float(params.width) || p.y > float(params.height);
}

// The part of [from, to] on the canvas, exact DDA (matches RayMarcher::segment).
Segment traceSegment(vec2 from, vec2 to) {
    Segment s = Segment(vec3(0.0), vec3(1.0), outside(to));
    const vec2 delta = to - from;
    const float len = length(delta);
    if (len <= 0.0) return s;
    const vec2 dir = delta / len;
    // Clip to the canvas box.
    float t0 = 0.0, t1 = len;
    const vec2 hi = vec2(float(params.width), float(params.height));
    for (int a = 0; a < 2; ++a) {
        if (dir[a] == 0.0) {
            if (from[a] < 0.0 || from[a] > hi[a]) return s;
            continue;
        }
        float ta = (0.0 - from[a]) / dir[a], tb = (hi[a] - from[a]) / dir[a];
        if (ta > tb) { const float tmp = ta; ta = tb; tb = tmp; }
        t0 = max(t0, ta);
        t1 = min(t1, tb);
    }
    if (t0 >= t1) return s;
    const vec2 start = clamp(from + dir * t0, vec2(0.0), hi);
    const Marched m = marchMedium(start, dir, t1 - t0, params.width, params.height, 1e-6, 1.0);
    s.radiance = m.radiance;
    s.transmittance = m.transmittance;
    return s;
}

vec3 upperValue(int ux, int uy, int k) {
    return texelRgb(upper[(uint(uy) * params.upperProbesX + uint(ux)) * params.upperStored + uint(k)]);
}

vec3 sky() { return vec3(params.skyR, params.skyG, params.skyB); }

vec3 mergedRay(vec2 p, int k) {
    const vec2 dir = rcDirection(k, int(params.rays));
    const vec2 start = p + dir * params.intervalStart;
    if (params.hasUpper == 0u) {
        const Segment seg = traceSegment(start, p + dir * params.intervalEnd);
        return seg.radiance + seg.transmittance * sky();
    }
    const vec2 upperOffset = vec2(params.upperOffsetX, params.upperOffsetY);
    const RcBilinear f = rcBilinearAt(p - upperOffset, params.upperSpacing,
                                      int(params.upperProbesX), int(params.upperProbesY));
    if (params.bilinearFix == 0u) {
        const Segment seg = traceSegment(start, p + dir * params.intervalEnd);
        vec3 beyond = sky();
        if (!seg.leaves) {
            beyond = vec3(0.0);
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b)
                    beyond += upperValue(rcBilinearX(f, a), rcBilinearY(f, b), k) *
                              rcBilinearWeight(f, a, b);
        }
        return seg.radiance + seg.transmittance * beyond;
    }
    vec3 sum = vec3(0.0);
    for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
            const int ux = rcBilinearX(f, a), uy = rcBilinearY(f, b);
            const vec2 q = rcProbeCentre(ux, uy, params.upperSpacing) + upperOffset;
            const Segment seg = traceSegment(start, q + dir * params.upperIntervalStart);
            const vec3 beyond = seg.leaves ? sky() : upperValue(ux, uy, k);
            sum += (seg.radiance + seg.transmittance * beyond) * rcBilinearWeight(f, a, b);
        }
    }
    return sum;
}

void main() {
    const uint index = LUXEL_LINEAR_INVOCATION;
    const uint total = params.probesX * params.probesY * params.stored;
    if (index >= total) return;
    const uint probe = index / params.stored, s = index % params.stored;
    const uint px = probe % params.probesX, py = probe / params.probesX;
    const vec2 p = rcProbeCentre(int(px), int(py), params.spacing) +
                   vec2(params.offsetX, params.offsetY);
    const uint group = uint(rcGroup(int(params.rays), int(params.stored)));
    vec3 sum = vec3(0.0);
    for (uint k = s * group; k < (s + 1u) * group; ++k) sum += mergedRay(p, int(k));
    sum /= float(group);
    current[index] = rgbTexel(sum);
}
