// Dispatching the post passes: images travel as packed RGB floats (post_layout.h).
#include "luxel/post/post_gpu.h"

#include <algorithm>
#include <memory>

#include "gpu/shaders/shared/post_layout.h"
#include "luxel/gpu/context.h"
#include "luxel/post/bloom.h"
#include "post/sample.h"

namespace luxel::post {
namespace {

namespace shared = gpu::shared;
using u32 = std::uint32_t;

// Device buffers of one run, freed when it returns.
struct Scratch {
    gpu::Context& context;
    std::vector<std::shared_ptr<gpu::Buffer>> held;

    Result<gpu::Buffer*> create(std::uint64_t bytes) {
        auto b = context.createBuffer(std::max<std::uint64_t>(bytes, 4));
        if (!b) return b.error();
        held.push_back(*b);
        return held.back().get();
    }
    Result<gpu::Buffer*> upload(const Image& image) {
        auto b = create(image.size() * sizeof(float));
        if (!b) return b;
        if (Status s = context.upload(**b, std::as_bytes(std::span(image.data(), image.size())));
            !s) {
            return s.error();
        }
        return b;
    }
};

Result<Image> download(gpu::Context& context, const gpu::Buffer& buffer, int w, int h) {
    Image image(w, h, 3);
    if (Status s =
            context.download(buffer, std::as_writable_bytes(std::span(image.data(), image.size())));
        !s) {
        return s.error();
    }
    return image;
}

shared::PostResampleParams params(int sw, int sh, int dw, int dh, bool karis = false,
                                  float baseWeight = 0, float lowWeight = 0) {
    return {u32(sw), u32(sh), u32(dw), u32(dh), karis ? 1u : 0u, 0u, baseWeight, lowWeight};
}

gpu::Dispatch dispatch(const char* name, gpu::Program* program, std::vector<gpu::Buffer*> buffers,
                       const shared::PostResampleParams& p) {
    gpu::Dispatch d;
    d.name = name;
    d.program = program;
    d.buffers = std::move(buffers);
    d.setPush(p);
    d.setThreads(p.dstWidth, p.dstHeight);
    return d;
}

Status record(std::vector<gpu::PassTiming>* timings,
              const Result<std::vector<gpu::PassTiming>>& run) {
    if (!run) return run.error();
    if (timings) timings->insert(timings->end(), run->begin(), run->end());
    return Ok{};
}

}  // namespace

Result<Image> bloomDownsampleGpu(gpu::Context& context, const Image& source, bool karis) {
    const Image src = detail::toRgb(source);
    const int w = std::max(1, (src.width() + 1) / 2), h = std::max(1, (src.height() + 1) / 2);
    auto program = context.program("post_bloom_down", 2, sizeof(shared::PostResampleParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    auto in = scratch.upload(src);
    if (!in) return in.error();
    auto out = scratch.create(std::uint64_t(w) * h * 3 * sizeof(float));
    if (!out) return out.error();
    const gpu::Dispatch d = dispatch("bloom down", *program, {*in, *out},
                                     params(src.width(), src.height(), w, h, karis));
    if (Status s = record(nullptr, context.run(std::span(&d, 1))); !s) return s.error();
    return download(context, **out, w, h);
}

Result<Image> bloomUpsampleAddGpu(gpu::Context& context, const Image& lowIn, const Image& baseIn,
                                  float baseWeight, float lowWeight) {
    const Image low = detail::toRgb(lowIn), base = detail::toRgb(baseIn);
    auto program = context.program("post_bloom_up", 3, sizeof(shared::PostResampleParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    auto l = scratch.upload(low);
    if (!l) return l.error();
    auto b = scratch.upload(base);
    if (!b) return b.error();
    auto out = scratch.create(base.size() * sizeof(float));
    if (!out) return out.error();
    const gpu::Dispatch d = dispatch("bloom up", *program, {*l, *b, *out},
                                     params(low.width(), low.height(), base.width(), base.height(),
                                            false, baseWeight, lowWeight));
    if (Status s = record(nullptr, context.run(std::span(&d, 1))); !s) return s.error();
    return download(context, **out, base.width(), base.height());
}

Result<Image> bloomGpu(gpu::Context& context, const Image& hdr, const BloomSettings& settings,
                       std::vector<gpu::PassTiming>* timings) {
    const Image input = detail::toRgb(hdr);
    const int levels = bloomLevels(input.width(), input.height(), settings.levels);
    const float strength = std::clamp(settings.strength, 0.0f, 1.0f);
    if (levels == 0 || strength == 0.0f) return input;
    auto down = context.program("post_bloom_down", 2, sizeof(shared::PostResampleParams));
    if (!down) return down.error();
    auto up = context.program("post_bloom_up", 3, sizeof(shared::PostResampleParams));
    if (!up) return up.error();
    Scratch scratch{context, {}};
    auto in = scratch.upload(input);
    if (!in) return in.error();
    // Level k + 1 of the chain and, for k < levels - 1, its accumulated sum.
    std::vector<gpu::Buffer*> chain, acc;
    std::vector<std::pair<int, int>> sizes{{input.width(), input.height()}};
    std::vector<gpu::Dispatch> passes;
    for (int k = 0; k < levels; ++k) {
        const auto [sw, sh] = sizes.back();
        const int w = (sw + 1) / 2, h = (sh + 1) / 2;
        auto level = scratch.create(std::uint64_t(w) * h * 3 * sizeof(float));
        if (!level) return level.error();
        auto sum = scratch.create(std::uint64_t(w) * h * 3 * sizeof(float));
        if (!sum) return sum.error();
        passes.push_back(dispatch("bloom down", *down, {k == 0 ? *in : chain.back(), *level},
                                  params(sw, sh, w, h, k == 0 && settings.karisAverage)));
        chain.push_back(*level);
        acc.push_back(*sum);
        sizes.push_back({w, h});
    }
    // acc_k = level_k + up(acc_{k+1}); the top of the chain is its own sum.
    gpu::Buffer* lower = chain.back();
    for (int k = levels - 2; k >= 0; --k) {
        const auto [w, h] = sizes[k + 1];
        const auto [lw, lh] = sizes[k + 2];
        passes.push_back(dispatch("bloom up", *up, {lower, chain[k], acc[k]},
                                  params(lw, lh, w, h, false, 1, 1)));
        lower = acc[k];
    }
    auto out = scratch.create(input.size() * sizeof(float));
    if (!out) return out.error();
    passes.push_back(dispatch("bloom combine", *up, {lower, *in, *out},
                              params(sizes[1].first, sizes[1].second, input.width(), input.height(),
                                     false, 1.0f - strength, strength / float(levels))));
    if (Status s = record(timings, context.run(passes)); !s) return s.error();
    return download(context, **out, input.width(), input.height());
}

Result<Image> upscaleEdgeGpu(gpu::Context& context, const Image& source, int width, int height,
                             std::vector<gpu::PassTiming>* timings) {
    const Image src = detail::toRgb(source);
    auto program = context.program("post_upscale", 2, sizeof(shared::PostResampleParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    auto in = scratch.upload(src);
    if (!in) return in.error();
    auto out = scratch.create(std::uint64_t(width) * height * 3 * sizeof(float));
    if (!out) return out.error();
    const gpu::Dispatch d = dispatch("upscale edge", *program, {*in, *out},
                                     params(src.width(), src.height(), width, height));
    if (Status s = record(timings, context.run(std::span(&d, 1))); !s) return s.error();
    return download(context, **out, width, height);
}

Result<TrigGpuRun> trigGpu(gpu::Context& context, std::span<const float> inputs,
                           TrigFunction function, int terms, int iterations) {
    auto program = context.program("post_trig_timing", 2, sizeof(shared::PostTrigParams));
    if (!program) return program.error();
    Scratch scratch{context, {}};
    auto in = scratch.create(inputs.size_bytes());
    if (!in) return in.error();
    if (Status s = context.upload(**in, std::as_bytes(inputs)); !s) return s.error();
    auto out = scratch.create(inputs.size_bytes());
    if (!out) return out.error();
    gpu::Dispatch d;
    d.name = "trig";
    d.program = *program;
    d.buffers = {*in, *out};
    d.setPush(shared::PostTrigParams{u32(inputs.size()), u32(std::max(iterations, 1)),
                                     u32(function), u32(std::max(terms, 1))});
    d.setLinearThreads(inputs.size());
    auto run = context.run(std::span(&d, 1));
    if (!run) return run.error();
    TrigGpuRun result;
    result.milliseconds = run->front().milliseconds;
    result.values.resize(inputs.size());
    if (Status s = context.download(**out, std::as_writable_bytes(std::span(result.values))); !s) {
        return s.error();
    }
    return result;
}

}  // namespace luxel::post
