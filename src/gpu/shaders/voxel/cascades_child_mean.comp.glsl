// Voxel radiance cascades: each bin's four children averaged by solid angle, for the level below
// (docs/algorithms/voxel-radiance-cascades.md §2; CPU: mergeLevel in
// src/voxel/cascades/cascade_light.cpp). One invocation per (probe, bin of the level below).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/medium_layout.h"
#include "shared/voxel_cascades_layout.h"

layout(local_size_x = LUXEL_CASCADES_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Radiance { RgbTexel radiance[]; };
layout(std430, set = 0, binding = 1) readonly buffer SolidAngle { float solidAngle[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Means { RgbTexel means[]; };
layout(push_constant) uniform Push { CascadeChildMeanParams params; };

void main() {
    const uint side = params.binSide, halfSide = side / 2u, parents = halfSide * halfSide;
    const uint index = LUXEL_LINEAR_INVOCATION;
    if (index >= params.probes * parents) return;
    const uint p = index / parents, b = index % parents;
    const uint bx = 2u * (b % halfSide), by = 2u * (b / halfSide);
    const uint children[4] = uint[4](by * side + bx, by * side + bx + 1u, (by + 1u) * side + bx,
                                     (by + 1u) * side + bx + 1u);
    vec3 sum = vec3(0.0);
    float area = 0.0;
    for (int i = 0; i < 4; ++i) {
        const float a = solidAngle[params.solidAngleOffset + children[i]];
        sum += texelRgb(radiance[params.radianceOffset + p * side * side + children[i]]) * a;
        area += a;
    }
    means[params.meanOffset + index] = rgbTexel(sum * (1.0 / area));
}
