// Post-processing structures shared by C++ and GLSL (offsets checked below and, against the
// compiled shaders, in tests/gpu/post_gpu_test.cpp).
//
// Images are float RGB, three floats per pixel, rows top to bottom: the layout of a 3-channel
// luxel::Image, so buffers upload and download without repacking.
#ifndef LUXEL_GPU_SHARED_POST_LAYOUT_H
#define LUXEL_GPU_SHARED_POST_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace luxel::gpu::shared {
using uint = std::uint32_t;
#endif

// Workgroup side of every post pass (8 x 8 invocations).
#define LUXEL_POST_GROUP 8

// Push constants of the resampling passes. post_bloom_down: dst = down(src) (karis != 0: Karis
// average). post_bloom_up: dst = baseWeight * base + lowWeight * up(src), base at dst's size.
// post_upscale: dst = edge-aware upscale of src (sharpness is unused there).
struct PostResampleParams {
    uint srcWidth;
    uint srcHeight;
    uint dstWidth;
    uint dstHeight;
    uint karis;
    uint pad0;
    float baseWeight;
    float lowWeight;
};

// Push constants of post_trig_timing: `iterations` evaluations per invocation of `function`
// (0: sin, 1: Taylor sin, 2: asin, 3: Taylor asin, 4: minimax asin), Taylor terms `terms`.
struct PostTrigParams {
    uint count;
    uint iterations;
    uint function;
    uint terms;
};

#ifdef __cplusplus
static_assert(sizeof(PostResampleParams) == 32);
static_assert(offsetof(PostResampleParams, baseWeight) == 24);
static_assert(sizeof(PostTrigParams) == 16);
}  // namespace luxel::gpu::shared
#endif

#endif
