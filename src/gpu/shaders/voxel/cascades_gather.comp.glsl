// Voxel radiance cascades: each face's irradiance through its own segments and level 0
// (docs/algorithms/voxel-radiance-cascades.md §4; CPU: lightingPass in
// src/voxel/cascades/cascade_light.cpp). One invocation per face.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/medium_layout.h"
#include "shared/voxel_cascades_layout.h"

layout(local_size_x = LUXEL_CASCADES_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Codes { uint codes[]; };
layout(std430, set = 0, binding = 1) readonly buffer Corners { uint corners[]; };
layout(std430, set = 0, binding = 2) buffer FaceLight { RgbTexel light[]; };
layout(std430, set = 0, binding = 3) readonly buffer Sky { RgbTexel sky[]; };
layout(std430, set = 0, binding = 4) readonly buffer Radiance { RgbTexel radiance[]; };
layout(std430, set = 0, binding = 5) readonly buffer FaceInfo { uint faceInfo[]; };
layout(std430, set = 0, binding = 6) readonly buffer CosineBins { uint cosineBins[]; };
layout(push_constant) uniform Push { CascadeGatherParams params; };

#include "voxel/cascades_chain.glsl"

void main() {
    const uint f = LUXEL_LINEAR_INVOCATION;
    if (f >= params.faces) return;
    const uint normal = faceInfo[2u * f], first = faceInfo[2u * f + 1u];
    const uint corner = (params.cornerOffset + f) * 16u;
    vec3 irradiance = vec3(0.0);
    for (uint i = 0u; i < params.normalCount[normal]; ++i) {
        const uint entry = 2u * (params.normalFirst[normal] + i);
        const uint b = cosineBins[entry];
        vec3 sum = vec3(0.0);
        float weight = 0.0;
        for (uint c = 0u; c < 8u; ++c) {
            const uint code = codes[first + i * 8u + c];
            const float w = uintBitsToFloat(corners[corner + 8u + c]);
            if (code == LUXEL_CASCADE_VOID || w == 0.0) continue;
            vec3 passed = vec3(0.0), through = vec3(1.0);
            const uint end = cascadeFollowPassages(code, params.faces, passed, through);
            vec3 value = vec3(0.0);
            if (end < LUXEL_CASCADE_PASSAGE) {
                value = texelRgb(light[LUXEL_FACE_OUTGOING * params.faces + end]);
            } else if (end == LUXEL_CASCADE_CONTINUE) {
                value = texelRgb(radiance[corners[corner + c] * params.levelBins + b]);
            } else if (end == LUXEL_CASCADE_SKY) {
                value = texelRgb(sky[params.skyOffset + b]);
            }
            sum += (passed + through * value) * w;
            weight += w;
        }
        const vec3 incoming = weight > 0.0 ? sum * (1.0 / weight) : vec3(0.0);
        irradiance += incoming * uintBitsToFloat(cosineBins[entry + 1u]);
    }
    light[LUXEL_FACE_IRRADIANCE * params.faces + f] = rgbTexel(irradiance);
}
