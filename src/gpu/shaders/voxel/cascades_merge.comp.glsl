// Voxel radiance cascades: one level merged from the level above
// (docs/algorithms/voxel-radiance-cascades.md §4; CPU: mergeLevel in
// src/voxel/cascades/cascade_light.cpp). One invocation per (probe, bin).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/medium_layout.h"
#include "shared/voxel_cascades_layout.h"

layout(local_size_x = LUXEL_CASCADES_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) readonly buffer Codes { uint codes[]; };
layout(std430, set = 0, binding = 1) readonly buffer Corners { uint corners[]; };
layout(std430, set = 0, binding = 2) readonly buffer FaceLight { RgbTexel light[]; };
layout(std430, set = 0, binding = 3) readonly buffer Sky { RgbTexel sky[]; };
layout(std430, set = 0, binding = 4) readonly buffer Means { RgbTexel means[]; };
layout(std430, set = 0, binding = 5) buffer Radiance { RgbTexel radiance[]; };
layout(push_constant) uniform Push { CascadeMergeParams params; };

#include "voxel/cascades_chain.glsl"

// What the chain of `code` brings, through its passages; upperMean: the level above's child
// mean to read where it ends in CONTINUE.
vec3 chainRadiance(uint code, uint bin, uint upperMean) {
    vec3 sum = vec3(0.0), through = vec3(1.0);
    code = cascadeFollowPassages(code, params.faces, sum, through);
    vec3 value = vec3(0.0);
    if (code < LUXEL_CASCADE_PASSAGE) {
        value = texelRgb(light[LUXEL_FACE_OUTGOING * params.faces + code]);
    } else if (code == LUXEL_CASCADE_CONTINUE && params.top == 0u) {
        value = texelRgb(means[upperMean]);
    } else if (code == LUXEL_CASCADE_SKY) {
        value = texelRgb(sky[params.skyOffset + bin]);
    }
    return sum + through * value;
}

void main() {
    const uint index = LUXEL_LINEAR_INVOCATION;
    if (index >= params.probes * params.bins) return;
    const uint p = index / params.bins, b = index % params.bins;
    vec3 result;
    if (params.top != 0u) {
        result = chainRadiance(codes[params.codeOffset + index], b, 0u);
    } else {
        const uint corner = (params.cornerOffset + p) * 16u;
        vec3 sum = vec3(0.0);
        float weight = 0.0;
        for (uint c = 0u; c < 8u; ++c) {
            const uint code = codes[params.codeOffset + index * 8u + c];
            const float w = uintBitsToFloat(corners[corner + 8u + c]);
            if (code == LUXEL_CASCADE_VOID || w == 0.0) continue;
            const uint upperMean = params.upperMeanOffset + corners[corner + c] * params.bins + b;
            sum += chainRadiance(code, b, upperMean) * w;
            weight += w;
        }
        result = weight > 0.0 ? sum * (1.0 / weight) : vec3(0.0);
    }
    radiance[params.radianceOffset + index] = rgbTexel(result);
}
