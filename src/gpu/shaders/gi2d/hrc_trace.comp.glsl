// HRC base intervals (docs/algorithms/holographic-radiance-cascades.md §3; CPU twin: traceLevel in
// src/gi2d/hrc/ray_tables.cpp): T_n(p, y, k) marched from (p 2^n, y + 0.5) over v_n(k) with the
// exact DDA of march2d.glsl, reading the canvas medium through the frustum's frame.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"
#include "shared/medium_layout.h"
#include "gi2d/hrc_common.glsl"

layout(local_size_x = LUXEL_HRC_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { MediumTexel medium[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Table { HrcTableEntry table[]; };
layout(push_constant) uniform Push { HrcTraceParams params; };

// Frame pixel (u, v) is canvas pixel hrcFrameToCanvas(...): the canvas medium serves all frustums.
uint mediumIndex(ivec2 cell, uint width) {
    const ivec2 c = hrcFrameToCanvas(params.frustum, cell, int(params.canvasWidth),
                                     int(params.canvasHeight));
    return params.transposed != 0u ? uint(c.x) * params.canvasHeight + uint(c.y)
                                   : uint(c.y) * params.canvasWidth + uint(c.x);
}

#include "gi2d/march2d.glsl"

void main() {
    const uint y = gl_GlobalInvocationID.x, k = gl_GlobalInvocationID.y;
    const uint p = gl_GlobalInvocationID.z;
    if (y >= params.rows || p >= params.planes) return;
    const float dx = float(1u << params.level);
    const float dy = float(hrcRayOffsetY(int(params.level), int(k)));
    const float len = sqrt(dx * dx + dy * dy);
    const vec2 dir = vec2(dx, dy) / len;
    const vec2 origin = vec2(float(p) * dx, float(y) + 0.5);

    // The frame medium ends at the frame: empty space beyond (no cutoff: exact to the end).
    const Marched m =
        marchMedium(origin, dir, len, params.frameLength, params.rows, 0.0, params.depthScale);
    const HrcInterval v = HrcInterval(m.radiance, m.transmittance);
    table[tableIndex(params.level, p, k, y, params.rows)] = packEntry(v);
}
