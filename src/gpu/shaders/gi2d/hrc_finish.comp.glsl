// HRC finish (CPU twin: finishFluence in src/gi2d/hrc/finish.cpp):
// opacity-gated cross blur of the light arriving at the read-out planes (paper Eq 21), then the
// pixel's own half-pixel segment in front, then / 2 pi (mean radiance over directions).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_kernels.h"
#include "shared/hrc_layout.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { float medium[]; };
layout(std430, set = 0, binding = 1) readonly buffer Beyond { float beyond[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Fluence { float fluence[]; };
layout(push_constant) uniform Push { HrcFinishParams params; };

vec3 sigmaAt(int x, int y) {
    const uint b = (uint(y) * params.width + uint(x)) * 6u;
    return vec3(medium[b], medium[b + 1u], medium[b + 2u]);
}

float opacityAt(int x, int y) {
    return hrcOpacity(sigmaAt(x, y));
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
            if (!hrcBlurTakes(centre, opacityAt(n.x, n.y))) continue;
            sum += beyondAt(n.x, n.y);
            total += 1.0;
        }
        arriving = sum / total;
    }
    const uint b = (uint(c.y) * params.width + uint(c.x)) * 6u;
    const vec3 sigma = vec3(medium[b], medium[b + 1u], medium[b + 2u]);
    const vec3 emission = vec3(medium[b + 3u], medium[b + 4u], medium[b + 5u]);
    const vec3 total = hrcFinishPixel(sigma, emission, arriving, float(params.frustums));
    const uint o = (uint(c.y) * params.width + uint(c.x)) * 3u;
    fluence[o] = total.x;
    fluence[o + 1u] = total.y;
    fluence[o + 2u] = total.z;
}
