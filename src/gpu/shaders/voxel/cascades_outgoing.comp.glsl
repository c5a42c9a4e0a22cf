// Voxel radiance cascades: what each face sends this pass
// (docs/algorithms/voxel-radiance-cascades.md §4; CPU: lightingPass in
// src/voxel/cascades/cascade_light.cpp). One invocation per face.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/medium_layout.h"
#include "shared/voxel_cascades_layout.h"

layout(local_size_x = LUXEL_CASCADES_GROUP_SIZE) in;
layout(std430, set = 0, binding = 0) buffer FaceLight { RgbTexel light[]; };
layout(push_constant) uniform Push { CascadeOutgoingParams params; };

vec3 section(uint s, uint f) { return texelRgb(light[s * params.faces + f]); }

void main() {
    const uint f = LUXEL_LINEAR_INVOCATION;
    if (f >= params.faces) return;
    const vec3 received = section(LUXEL_FACE_DIRECT, f) + section(LUXEL_FACE_IRRADIANCE, f) +
                          section(LUXEL_FACE_EMITTER, f);
    light[LUXEL_FACE_OUTGOING * params.faces + f] = rgbTexel(
        section(LUXEL_FACE_EMITTED, f) + section(LUXEL_FACE_ALBEDO, f) * received * 0.31830988618f);
}
