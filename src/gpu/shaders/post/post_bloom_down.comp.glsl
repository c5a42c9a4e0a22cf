// Bloom downsample (CPU twin: bloomDownsample in src/post/bloom.cpp): the 5-tap dual filter
// (Bjørge 2015), optionally Karis-weighted.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/post_kernels.h"
#include "shared/post_layout.h"

layout(local_size_x = LUXEL_POST_GROUP, local_size_y = LUXEL_POST_GROUP) in;
layout(std430, set = 0, binding = 0) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Dst { float dst[]; };
layout(push_constant) uniform Push { PostResampleParams params; };

#include "post/post_common.glsl"

void main() {
    const ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (c.x >= int(params.dstWidth) || c.y >= int(params.dstHeight)) return;
    const vec2 p = postDownPosition(c.x, c.y);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int t = 0; t < 5; ++t) {
        const vec3 s = srcBilinear(p + postDownTapOffset(t));
        const float w = postDownTapWeight(t) * (params.karis != 0u ? postKarisWeight(s) : 1.0);
        sum += s * w;
        total += w;
    }
    storeDst(c.x, c.y, sum * (1.0 / total));
}
