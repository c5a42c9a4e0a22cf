// HRC finish (CPU twin: finishFluence in src/gi2d/hrc/finish.cpp):
// opacity-gated cross blur of the light arriving at the read-out planes (paper Eq 21), then the
// pixel's own half-pixel segment in front, then / 2 pi (mean radiance over directions).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_kernels.h"
#include "shared/hrc_layout.h"
#include "shared/medium_layout.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { MediumTexel medium[]; };
layout(std430, set = 0, binding = 1) readonly buffer Beyond { RgbTexel beyond[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Fluence { RgbTexel fluence[]; };
layout(push_constant) uniform Push { HrcFinishParams params; };

vec3 sigmaAt(int x, int y) {
    return mediumSigma(medium[uint(y) * params.width + uint(x)]);
}

float opacityAt(int x, int y) {
    return hrcOpacity(sigmaAt(x, y));
}

vec3 beyondAt(int x, int y) {
    return texelRgb(beyond[uint(y) * params.width + uint(x)]);
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
    const uint pixel = uint(c.y) * params.width + uint(c.x);
    const MediumTexel m = medium[pixel];
    fluence[pixel] = rgbTexel(
        hrcFinishPixel(mediumSigma(m), mediumEmission(m), arriving, float(params.frustums)));
}
