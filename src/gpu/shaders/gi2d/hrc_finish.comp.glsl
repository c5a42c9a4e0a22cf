// HRC finish (CPU reference: crossBlur + the end of solveHrc in src/gi2d/hrc/hrc_solver.cpp):
// opacity-gated cross blur of the light arriving at the read-out planes (paper Eq 21), then the
// pixel's own half-pixel segment in front, then / 2 pi (mean radiance over directions).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { float medium[]; };
layout(std430, set = 0, binding = 1) readonly buffer Beyond { float beyond[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Fluence { float fluence[]; };
layout(push_constant) uniform Push { HrcFinishParams params; };

const float kQuarterTurn = 1.57079632679489662;
const float kInvTwoPi = 0.159154943091895336;

vec3 sigmaAt(int x, int y) {
    const uint b = (uint(y) * params.width + uint(x)) * 6u;
    return vec3(medium[b], medium[b + 1u], medium[b + 2u]);
}

float opacityAt(int x, int y) {
    const vec3 s = sigmaAt(x, y);
    return 1.0 - exp(-max(s.x, max(s.y, s.z)));
}

vec3 beyondAt(int x, int y) {
    const uint b = (uint(y) * params.width + uint(x)) * 3u;
    return vec3(beyond[b], beyond[b + 1u], beyond[b + 2u]);
}

void main() {
    const ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (c.x >= int(params.width) || c.y >= int(params.height)) return;
    vec3 arriving = beyondAt(c.x, c.y);
    if (params.blur != 0u) {
        const float centre = opacityAt(c.x, c.y);
        vec3 sum = arriving * 4.0;
        float total = 4.0;
        const ivec2 taps[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
        for (int t = 0; t < 4; ++t) {
            const ivec2 n = c + taps[t];
            if (n.x < 0 || n.y < 0 || n.x >= int(params.width) || n.y >= int(params.height)) continue;
            if (abs(opacityAt(n.x, n.y) - centre) > 0.1) continue;
            sum += beyondAt(n.x, n.y);
            total += 1.0;
        }
        arriving = sum / total;
    }
    const uint b = (uint(c.y) * params.width + uint(c.x)) * 6u;
    const vec3 sigma = vec3(medium[b], medium[b + 1u], medium[b + 2u]);
    const vec3 emission = vec3(medium[b + 3u], medium[b + 4u], medium[b + 5u]);
    const vec3 t = exp(-0.5 * sigma);
    const vec3 total = emission * (vec3(1.0) - t) * (kQuarterTurn * float(params.frustums)) +
                       t * arriving;
    const uint o = (uint(c.y) * params.width + uint(c.x)) * 3u;
    fluence[o] = total.x * kInvTwoPi;
    fluence[o + 1u] = total.y * kInvTwoPi;
    fluence[o + 2u] = total.z * kInvTwoPi;
}
