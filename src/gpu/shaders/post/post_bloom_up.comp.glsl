// Bloom upsample (CPU twin: bloomUpsampleAdd in src/post/bloom.cpp): the 8-tap dual filter
// (Bjørge 2015) of the lower level, weighted and added to the level above.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/post_kernels.h"
#include "shared/post_layout.h"

layout(local_size_x = LUXEL_POST_GROUP, local_size_y = LUXEL_POST_GROUP) in;
layout(std430, set = 0, binding = 0) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 1) readonly buffer Base { float base[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Dst { float dst[]; };
layout(push_constant) uniform Push { PostResampleParams params; };

#include "post/post_common.glsl"

void main() {
    const ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (c.x >= int(params.dstWidth) || c.y >= int(params.dstHeight)) return;
    const vec2 p = postUpPosition(c.x, c.y);
    vec3 sum = vec3(0.0);
    for (int t = 0; t < 8; ++t) {
        sum += srcBilinear(p + postUpTapOffset(t) * 0.5) * postUpTapWeight(t);
    }
    const uint i = (uint(c.y) * params.dstWidth + uint(c.x)) * 3u;
    const vec3 b = vec3(base[i], base[i + 1u], base[i + 2u]);
    storeDst(c.x, c.y, b * params.baseWeight + sum * params.lowWeight);
}
