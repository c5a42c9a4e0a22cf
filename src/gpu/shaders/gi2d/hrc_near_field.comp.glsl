// HRC's exact near field in fog (docs/algorithms/holographic-radiance-cascades.md §12.3; CPU twin:
// nearFieldGatherAt in src/gi2d/hrc/near_field.cpp): a workgroup per listed pixel and an
// invocation per direction 2 pi (k + 1/2) / rays, marched from the pixel centre with the exact DDA
// of march2d.glsl; the workgroup's mean radiance is written over HRC's fluence.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/hrc_layout.h"
#include "shared/medium_layout.h"

layout(local_size_x = LUXEL_HRC_NEAR_FIELD_RAYS) in;
layout(std430, set = 0, binding = 0) readonly buffer Medium { MediumTexel medium[]; };
layout(std430, set = 0, binding = 1) readonly buffer Pixels { uint pixels[]; };
layout(std430, set = 0, binding = 2) buffer Fluence { RgbTexel fluence[]; };
layout(push_constant) uniform Push { HrcNearFieldParams params; };

uint mediumIndex(ivec2 cell, uint width) {
    return uint(cell.y) * width + uint(cell.x);
}

#include "gi2d/march2d.glsl"

shared vec3 radiance[LUXEL_HRC_NEAR_FIELD_RAYS];

void main() {
    // The runtime folds the workgroups into rows of at most 65535 (Dispatch::setLinearThreads);
    // the test is uniform over the workgroup, so no invocation misses the barriers below.
    const uint i = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
    if (i >= params.count) return;
    const uint k = gl_LocalInvocationID.x;
    const uint pixel = pixels[i];
    const vec2 origin = vec2(float(pixel % params.width) + 0.5, float(pixel / params.width) + 0.5);
    const float angle = (float(k) + 0.5) * (6.283185307179586 / float(params.rays));
    const Marched m = marchMedium(origin, vec2(cos(angle), sin(angle)), params.reach,
                                  params.width, params.height, params.cutoff, 1.0);
    // A march ends at the reach or the cutoff (T below it) or at the canvas's edge, where the sky
    // shows through.
    const vec2 end = origin + vec2(cos(angle), sin(angle)) * params.reach;
    const bool left = max(m.transmittance.x, max(m.transmittance.y, m.transmittance.z)) >=
                          params.cutoff &&
                      (end.x < 0.0 || end.y < 0.0 || end.x > float(params.width) ||
                       end.y > float(params.height));
    radiance[k] = m.radiance + (left ? m.transmittance * vec3(params.skyR, params.skyG,
                                                              params.skyB)
                                     : vec3(0.0));
    barrier();
    // A tree sum in a fixed order: the same bits on every run.
    for (uint stride = LUXEL_HRC_NEAR_FIELD_RAYS / 2u; stride > 0u; stride /= 2u) {
        if (k < stride) radiance[k] += radiance[k + stride];
        barrier();
    }
    if (k == 0u) fluence[pixel] = rgbTexel(radiance[0] / float(params.rays));
}
