// The GPU twins of the post passes (Vulkan compute, src/gpu/shaders/post/): bloom's down and up
// passes and the edge-aware upscaler, on the same shared formulas as the CPU
// (src/gpu/shaders/shared/post_kernels.h); tests/gpu/post_gpu_test.cpp checks parity. Also the
// device timing of built-in sin/asin against polynomial ones
// (docs/algorithms/trig-approximations.md).
#pragma once

#include <span>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/post/post_options.h"

namespace luxel::gpu {
class Context;
struct PassTiming;
}  // namespace luxel::gpu

namespace luxel::post {

Result<Image> bloomDownsampleGpu(gpu::Context& context, const Image& src, bool karis);
Result<Image> bloomUpsampleAddGpu(gpu::Context& context, const Image& low, const Image& base,
                                  float baseWeight, float lowWeight);
// The whole chain in one submission; `timings` receives every pass.
Result<Image> bloomGpu(gpu::Context& context, const Image& hdr, const BloomSettings& settings,
                       std::vector<gpu::PassTiming>* timings = nullptr);
Result<Image> upscaleEdgeGpu(gpu::Context& context, const Image& src, int width, int height,
                             std::vector<gpu::PassTiming>* timings = nullptr);

enum class TrigFunction { Sin, TaylorSin, Asin, TaylorAsin, MinimaxAsin };

struct TrigGpuRun {
    std::vector<float> values;  // with iterations == 1: f(inputs[i]); else sums (timing only)
    double milliseconds = 0;    // the dispatch, from GPU timestamps
};
// `iterations` evaluations of `function` per input (Taylor: `terms` terms).
Result<TrigGpuRun> trigGpu(gpu::Context& context, std::span<const float> inputs,
                           TrigFunction function, int terms, int iterations);

}  // namespace luxel::post
