// HRC's exact near field in fog (docs/algorithms/holographic-radiance-cascades.md §12.3; CPU twin:
// nearFieldGatherAt in src/gi2d/hrc/near_field.cpp): one invocation per listed pixel, the mean
// radiance over params.rays directions 2 pi (k + 1/2) / rays marched from the pixel centre with
// the exact DDA of march2d.glsl, written over HRC's fluence.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/glsl_compat.h"
#include "shared/hrc_layout.h"
#include "shared/medium_layout.h"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { MediumTexel medium[]; };
layout(std430, set = 0, binding = 1) readonly buffer Pixels { uint pixels[]; };
layout(std430, set = 0, binding = 2) buffer Fluence { RgbTexel fluence[]; };
layout(push_constant) uniform Push { HrcNearFieldParams params; };

uint mediumIndex(ivec2 cell, uint width) {
    return uint(cell.y) * width + uint(cell.x);
}

#include "gi2d/march2d.glsl"

void main() {
    const uint i = LUXEL_LINEAR_INVOCATION;
    if (i >= params.count) return;
    const uint pixel = pixels[i];
    const vec2 origin = vec2(float(pixel % params.width) + 0.5, float(pixel / params.width) + 0.5);
    const vec3 sky = vec3(params.skyR, params.skyG, params.skyB);
    const float step = 6.283185307179586 / float(params.rays);
    vec3 sum = vec3(0.0);
    for (uint k = 0u; k < params.rays; ++k) {
        const float angle = (float(k) + 0.5) * step;
        const Marched m = marchMedium(origin, vec2(cos(angle), sin(angle)), 1e30, params.width,
                                      params.height, params.cutoff, 1.0);
        // The march ends at the cutoff or at the canvas's edge, where the sky shows through.
        const bool left = max(m.transmittance.x, max(m.transmittance.y, m.transmittance.z)) >=
                          params.cutoff;
        sum += m.radiance + (left ? m.transmittance * sky : vec3(0.0));
    }
    fluence[pixel] = rgbTexel(sum / float(params.rays));
}
