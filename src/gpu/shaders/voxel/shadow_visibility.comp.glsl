// Sun visibility for a batch of surface points, one invocation per point: sun_visibility.glsl as a
// pass of its own, compared point by point with the CPU (SunVisibility::visibility) in
// tests/gpu/shadow_gpu_test.cpp. Buffers: shared/shadow_layout.h.
#version 450
#extension GL_GOOGLE_include_directive : require

#define LUXEL_SHADOW_BINDING_PARAMS 0
#define LUXEL_SHADOW_BINDING_MOMENTS 1
#define LUXEL_SHADOW_BINDING_FIELD 2
#define LUXEL_SHADOW_BINDING_LEVELS 3
#include "voxel/sun_visibility.glsl"

layout(local_size_x = LUXEL_SHADOW_GROUP) in;
layout(std430, set = 0, binding = 4) readonly buffer Queries { ShadowQueryGpu queries[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Visibility { float visibility[]; };
layout(push_constant) uniform Push { ShadowBatchPush batch; };

void main() {
    uint i = LUXEL_LINEAR_INVOCATION;
    if (i >= batch.count) return;
    ShadowQueryGpu q = queries[i];
    visibility[i] = sunVisibility(vec3(q.x, q.y, q.z), ivec3(q.normalX, q.normalY, q.normalZ),
                                  q.footprint);
}
