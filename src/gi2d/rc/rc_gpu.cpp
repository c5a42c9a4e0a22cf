// Vanilla RC on the GPU: the CPU cascade loop (rc_solver.cpp) as one dispatch per cascade of
// src/gpu/shaders/gi2d/rc_cascade.comp.glsl (rc_cascade_pass.h); the read-out is shared with the
// CPU path.
#include <algorithm>
#include <string>

#include "gi2d/medium_gpu.h"
#include "gi2d/rc/rc_cascade_pass.h"
#include "gi2d/rc/rc_internal.h"
#include "gpu/shaders/shared/rc_layout.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gpu/context.h"

namespace luxel::gi2d {

namespace {

// One solve: options.jitters is 1 here (solveRcOnGpu averages over jitters).
Result<Image> solveOnceOnGpu(gpu::Context& context, const Medium2D& medium,
                             const RcOptions& options, std::vector<gpu::PassTiming>* timings) {
    const int w = medium.width(), h = medium.height();
    const std::vector<RcCascade> cascades = rcCascades(w, h, options);
    const int count = static_cast<int>(cascades.size());
    if (options.debugCascade >= count) {
        return Error("debug cascade " + std::to_string(options.debugCascade) +
                     " does not exist (this size has " + std::to_string(count) + ")");
    }
    std::uint64_t largest = 0;
    for (int i = 0; i < count; ++i) {
        largest = std::max<std::uint64_t>(largest, static_cast<std::uint64_t>(cascades[i].probesX) *
                                                       cascades[i].probesY *
                                                       rc::storedPerProbe(cascades[i], i) * 12);
    }
    const std::uint64_t pixels = static_cast<std::uint64_t>(w) * h;
    const std::uint64_t needed = 2 * largest + pixels * 24;
    if (context.device().deviceLocalBytes > 0 && needed > context.device().deviceLocalBytes) {
        return Error("RC at " + std::to_string(w) + "x" + std::to_string(h) + " needs " +
                     formatBytes(needed) + " of device memory, the device has " +
                     formatBytes(context.device().deviceLocalBytes));
    }
    using gpu::shared::RcCascadeParams;
    auto program = context.program("rc_cascade", 3, sizeof(RcCascadeParams));
    if (!program) return program.error();
    auto mediumBuffer = context.createBuffer(pixels * 24);
    if (!mediumBuffer) return mediumBuffer.error();
    std::shared_ptr<gpu::Buffer> buffers[2];
    for (auto& b : buffers) {
        auto created = context.createBuffer(largest);
        if (!created) return created.error();
        b = *created;
    }
    {
        Stopwatch upload;
        const auto packed = packMediumForGpu(medium);
        if (Status s = context.upload(**mediumBuffer, std::as_bytes(std::span(packed))); !s) {
            return s.error();
        }
        if (timings) timings->push_back({"upload medium (CPU)", upload.milliseconds()});
    }

    const int lowest = std::max(options.debugCascade, 0);
    std::vector<gpu::Dispatch> passes;
    int current = 0;
    for (int i = count - 1; i >= lowest; --i) {
        const bool top = i + 1 >= count;
        passes.push_back(rc::makeCascadeDispatch(
            *program, mediumBuffer->get(), top ? nullptr : buffers[current ^ 1].get(),
            buffers[current].get(), cascades, i, w, h, medium.boundaryRadiance, options.merge));
        current ^= 1;
    }
    auto ran = context.run(passes);
    if (!ran) return ran.error();
    if (timings) timings->insert(timings->end(), ran->begin(), ran->end());

    const RcCascade& c = cascades[lowest];
    std::vector<Rgb> values(static_cast<std::size_t>(c.probesX) * c.probesY *
                            rc::storedPerProbe(c, lowest));
    static_assert(sizeof(Rgb) == 12);
    if (Status s =
            context.download(*buffers[current ^ 1], std::as_writable_bytes(std::span(values)));
        !s) {
        return s.error();
    }
    return rc::readOut(c, lowest, values, w, h, options.debugCascade >= 0);
}

}  // namespace

Result<Image> solveRcOnGpu(gpu::Context& context, const Medium2D& medium, const RcOptions& options,
                           std::vector<gpu::PassTiming>* timings) {
    if (Status s = rc::validate(options); !s) return s.error();
    return rc::averageJitters(options, [&](const RcOptions& one) {
        return solveOnceOnGpu(context, medium, one, timings);
    });
}

}  // namespace luxel::gi2d
