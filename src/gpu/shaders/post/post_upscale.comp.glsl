// Edge-aware upscaling (CPU twin: upscaleEdge in src/post/upscale.cpp): a 4 x 4 window shaped
// by the local edge (shared/post_kernels.h), clamped to the nearest 2 x 2 texels.
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
    const int w = int(params.srcWidth), h = int(params.srcHeight);
    const vec2 p = postSourcePosition(c.x, c.y, w, h, int(params.dstWidth), int(params.dstHeight));
    const float u = p.x - 0.5, v = p.y - 0.5;
    const int bx = int(floor(u)), by = int(floor(v));
    const vec2 f = vec2(u - floor(u), v - floor(v));
    vec3 colour[16];
    vec4 rows[4];
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            colour[j * 4 + i] = srcTexel(clamp(bx - 1 + i, 0, w - 1), clamp(by - 1 + j, 0, h - 1));
            rows[j][i] = postLuma(colour[j * 4 + i]);
        }
    }
    const PostEdge edge = postEdgeSetup(rows[0], rows[1], rows[2], rows[3], f);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            const float weight = postEdgeWeight(edge, vec2(float(i - 1) - f.x, float(j - 1) - f.y));
            sum += colour[j * 4 + i] * weight;
            total += weight;
        }
    }
    const vec3 lo = min(min(colour[5], colour[6]), min(colour[9], colour[10]));
    const vec3 hi = max(max(colour[5], colour[6]), max(colour[9], colour[10]));
    storeDst(c.x, c.y, clamp(sum * (1.0 / max(total, 1e-6)), lo, hi));
}
