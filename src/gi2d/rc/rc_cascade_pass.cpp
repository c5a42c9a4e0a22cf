#include "gi2d/rc/rc_cascade_pass.h"

#include <algorithm>
#include <string>

#include "gi2d/medium_gpu.h"
#include "gpu/shaders/shared/rc_layout.h"

namespace luxel::gi2d::rc {

gpu::Dispatch makeCascadeDispatch(gpu::Program* program, gpu::Buffer* medium, gpu::Buffer* upper,
                                  gpu::Buffer* current, const std::vector<RcCascade>& cascades,
                                  int i, int width, int height, Rgb sky, RcMerge merge) {
    const RcCascade& c = cascades[i];
    const bool top = i + 1 >= static_cast<int>(cascades.size());
    const RcCascade& up = top ? c : cascades[i + 1];
    const auto stored = static_cast<std::uint32_t>(storedPerProbe(c, i));
    gpu::shared::RcCascadeParams p{};
    p.width = static_cast<std::uint32_t>(width);
    p.height = static_cast<std::uint32_t>(height);
    p.probesX = static_cast<std::uint32_t>(c.probesX);
    p.probesY = static_cast<std::uint32_t>(c.probesY);
    p.rays = static_cast<std::uint32_t>(c.rays);
    p.stored = stored;
    p.upperProbesX = static_cast<std::uint32_t>(up.probesX);
    p.upperProbesY = static_cast<std::uint32_t>(up.probesY);
    p.upperStored = top ? 0u : static_cast<std::uint32_t>(storedPerProbe(up, i + 1));
    p.hasUpper = top ? 0u : 1u;
    p.bilinearFix = merge == RcMerge::BilinearFix ? 1u : 0u;
    p.spacing = static_cast<float>(c.spacing);
    p.upperSpacing = static_cast<float>(up.spacing);
    p.intervalStart = static_cast<float>(c.intervalStart);
    p.intervalEnd = static_cast<float>(c.intervalEnd);
    p.upperIntervalStart = static_cast<float>(up.intervalStart);
    p.skyR = sky.r, p.skyG = sky.g, p.skyB = sky.b;
    p.offsetX = static_cast<float>(c.offsetX), p.offsetY = static_cast<float>(c.offsetY);
    p.upperOffsetX = static_cast<float>(up.offsetX),
    p.upperOffsetY = static_cast<float>(up.offsetY);
    gpu::Dispatch d;
    d.name = "rc cascade " + std::to_string(i);
    d.program = program;
    // The top cascade reads no upper buffer; its output is bound twice then (never read).
    d.buffers = {medium, top || !upper ? current : upper, current};
    d.setPush(p);
    const std::uint64_t invocations = static_cast<std::uint64_t>(c.probesX) * c.probesY * stored;
    d.setLinearThreads(invocations);
    return d;
}

Result<double> cascadePassOnGpu(gpu::Context& context, const Medium2D& medium,
                                const std::vector<RcCascade>& cascades, int i,
                                const std::vector<Rgb>& upper, RcMerge merge,
                                std::vector<Rgb>& out) {
    static_assert(sizeof(Rgb) == 12);
    auto program = context.program("rc_cascade", 3, sizeof(gpu::shared::RcCascadeParams));
    if (!program) return program.error();
    const auto packed = packMediumForGpu(medium);
    auto mediumBuffer = context.createBuffer(packed.size() * sizeof(packed[0]));
    if (!mediumBuffer) return mediumBuffer.error();
    if (Status s = context.upload(**mediumBuffer, std::as_bytes(std::span(packed))); !s) {
        return s.error();
    }
    auto upperBuffer = context.createBuffer(std::max<std::size_t>(upper.size() * 12, 4));
    if (!upperBuffer) return upperBuffer.error();
    if (!upper.empty()) {
        if (Status s = context.upload(**upperBuffer, std::as_bytes(std::span(upper))); !s) {
            return s.error();
        }
    }
    const RcCascade& c = cascades[i];
    out.assign(static_cast<std::size_t>(c.probesX) * c.probesY * storedPerProbe(c, i), Rgb());
    auto current = context.createBuffer(out.size() * 12);
    if (!current) return current.error();
    const bool top = i + 1 >= static_cast<int>(cascades.size());
    const gpu::Dispatch d = makeCascadeDispatch(
        *program, mediumBuffer->get(), top ? nullptr : upperBuffer->get(), current->get(), cascades,
        i, medium.width(), medium.height(), medium.boundaryRadiance, merge);
    auto timings = context.run(std::span<const gpu::Dispatch>(&d, 1));
    if (!timings) return timings.error();
    if (Status s = context.download(**current, std::as_writable_bytes(std::span(out))); !s) {
        return s.error();
    }
    return timings->front().milliseconds;
}

}  // namespace luxel::gi2d::rc
