// HRC base intervals (docs/algorithms/holographic-radiance-cascades.md §3; CPU twin: traceLevel in src/gi2d/hrc/ray_tables.cpp):
// T_n(p, y, k) marched from (p 2^n, y + 0.5) over v_n(k) with an exact DDA, one cell at a time:
// L += T E (1 - exp(-sigma l)), T *= exp(-sigma l) for the exact length l inside each cell.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"
#include "shared/medium_layout.h"
#include "gi2d/hrc_common.glsl"

layout(local_size_x = LUXEL_HRC_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { MediumTexel medium[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Table { HrcTableEntry table[]; };
layout(push_constant) uniform Push { HrcTraceParams params; };

void main() {
    const uint y = gl_GlobalInvocationID.x, k = gl_GlobalInvocationID.y;
    const uint p = gl_GlobalInvocationID.z;
    if (y >= params.rows || p >= params.planes) return;
    const float dx = float(1u << params.level);
    const float dy = float(2 * int(k) - int(1u << params.level));
    const float len = sqrt(dx * dx + dy * dy);
    const vec2 dir = vec2(dx, dy) / len;
    const vec2 origin = vec2(float(p) * dx, float(y) + 0.5);

    // Amanatides-Woo: dir.x > 0 always; dir.y may be 0 (k = 2^(n-1)).
    ivec2 cell = ivec2(floor(origin));
    const ivec2 stepDir = ivec2(1, dir.y > 0.0 ? 1 : -1);
    const float invX = 1.0 / dir.x;
    const float invY = dir.y != 0.0 ? 1.0 / abs(dir.y) : 1e30;
    float nextX = (float(cell.x + 1) - origin.x) * invX;
    float nextY = dir.y > 0.0 ? (float(cell.y + 1) - origin.y) * invY
                : dir.y < 0.0 ? (origin.y - float(cell.y)) * invY
                              : 1e30;
    HrcInterval v = hrcEmptyInterval();
    float t = 0.0;
    while (t < len) {
        if (cell.x < 0 || cell.y < 0 || cell.x >= int(params.frameLength) || cell.y >= int(params.rows)) {
            break;  // left the frame: empty space beyond
        }
        const float exit = min(min(nextX, nextY), len);
        const float l = exit - t;
        const MediumTexel m = medium[uint(cell.y) * params.frameLength + uint(cell.x)];
        const vec3 sigma = mediumSigma(m);
        const vec3 emission = mediumEmission(m);
        const vec3 tr = exp(-sigma * l);
        v.radiance += v.transmittance * emission * (vec3(1.0) - tr);
        v.transmittance *= tr;
        t = exit;
        if (nextX <= nextY) {
            cell.x += stepDir.x;
            nextX += invX;
        } else {
            cell.y += stepDir.y;
            nextY += invY;
        }
    }
    table[tableIndex(params.level, p, k, y, params.rows)] = packEntry(v);
}
