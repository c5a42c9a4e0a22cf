// HRC on the GPU: the CPU pass structure (hrc_solver.cpp) as dispatches of the shaders in
// src/gpu/shaders/gi2d/hrc_*.comp.glsl (built by gpu_passes.h), one submission per frustum.
#include <algorithm>
#include <bit>
#include <string>
#include <utility>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/direct_light.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/gpu_passes.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/near_field.h"
#include "gi2d/hrc/near_lights.h"
#include "gi2d/hrc/ray_tables.h"
#include "gi2d/medium_gpu.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "gpu/shaders/shared/hrc_layout.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gpu/context.h"

namespace luxel::gi2d {

using namespace hrc;
namespace shared = gpu::shared;

namespace {

// Entries of T_n and R_n for the larger of the two frame orientations.
std::uint64_t tableEntries(int width, int height, int n) {
    std::uint64_t most = 0;
    for (int r = 0; r < 2; ++r) {
        const FrustumFrame f = makeFrame(static_cast<Frustum>(r), width, height);
        if (n >= cascadeCount(f.length)) continue;
        most = std::max<std::uint64_t>(
            most, static_cast<std::uint64_t>(planeCount(f.length, n)) * (pow2(n) + 1) * f.rows);
    }
    return most;
}

// Bytes of the largest R_n (binary16, hrc_layout.h) of either frame orientation.
std::uint64_t coneBytes(int width, int height) {
    std::uint64_t most = 0;
    for (int n = 0; n < hrcCascadeCount(width, height); ++n) {
        for (int r = 0; r < 2; ++r) {
            const FrustumFrame f = makeFrame(static_cast<Frustum>(r), width, height);
            if (n >= cascadeCount(f.length)) continue;
            most = std::max(most, ConeBuffer::bytesFor(planeCount(f.length, n), pow2(n), f.rows));
        }
    }
    return most;
}

}  // namespace

std::uint64_t estimateHrcGpuMemory(int width, int height) {
    std::uint64_t bytes = 0;
    for (int n = 0; n < hrcCascadeCount(width, height); ++n) {
        bytes += tableEntries(width, height, n) * LUXEL_HRC_ENTRY_WORDS * 4;
    }
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    bytes += 2 * coneBytes(width, height);            // two R buffers
    bytes += 2 * pixels * 24;                         // the canvas medium, row- and column-major
    bytes += 2 * pixels * 12;                         // accumulator and fluence
    bytes += NearLightMask::bytesFor(width, height);  // §12.3
    return bytes;
}

namespace {

// solveHrcOnGpu without the split of §12.5, on a medium whose light scores are `scores`: the
// near-light mask and the near field's plan are made from them, then they are freed.
Result<Image> solveCascadesOnGpu(gpu::Context& context, const Medium2D& medium, LightScores& scores,
                                 const HrcOptions& options, std::vector<gpu::PassTiming>* timings) {
    const int w = medium.width(), h = medium.height();
    auto record = [&](const std::string& name, double ms) {
        if (timings) timings->push_back({name, ms});
    };
    // Where the lights are (§12.3), told once on the CPU and read by cascade 0's merge, and the
    // exact near field's pixels where the medium bounds the rays, as solveHrc does.
    const NearLightMask mask = NearLightMask::fromScores(scores);
    const NearFieldPlan nearField =
        options.exactNearField && std::popcount(options.frustumMask & 0xFu) == 4
            ? planNearField(scores)
            : NearFieldPlan{};
    scores.release();

    // Programs.
    using shared::HrcExtendParams, shared::HrcFinishParams, shared::HrcMergeParams,
        shared::HrcReadoutParams, shared::HrcTraceParams;
    auto trace = context.program("hrc_trace", 2, sizeof(HrcTraceParams));
    auto extend = context.program("hrc_extend", 2, sizeof(HrcExtendParams));
    auto merge = context.program("hrc_merge", 5, sizeof(HrcMergeParams));
    auto readout = context.program("hrc_readout", 2, sizeof(HrcReadoutParams));
    auto finish = context.program("hrc_finish", 3, sizeof(HrcFinishParams));
    auto nearFieldPass = context.program("hrc_near_field", 3, sizeof(shared::HrcNearFieldParams));
    auto transpose = context.program("medium_transpose", 2, sizeof(shared::MediumTransposeParams));
    for (auto* p : {&trace, &extend, &merge, &readout, &finish, &nearFieldPass, &transpose}) {
        if (!*p) return p->error();
    }

    // Buffers shared by the frustums.
    const int levelsMax = hrcCascadeCount(w, h);
    const std::uint64_t pixels = static_cast<std::uint64_t>(w) * h;
    std::vector<std::shared_ptr<gpu::Buffer>> tables, weights;
    for (int n = 0; n < levelsMax; ++n) {
        auto t = context.createBuffer(tableEntries(w, h, n) * LUXEL_HRC_ENTRY_WORDS * 4);
        if (!t) return t.error();
        tables.push_back(*t);
        const std::vector<float> wn = coneWeights(n);
        auto wb = context.createBuffer(wn.size() * 4);
        if (!wb) return wb.error();
        if (Status s = context.upload(**wb, std::as_bytes(std::span(wn))); !s) return s.error();
        weights.push_back(*wb);
    }
    std::shared_ptr<gpu::Buffer> cones[2];
    for (auto& c : cones) {
        auto b = context.createBuffer(coneBytes(w, h));
        if (!b) return b.error();
        c = *b;
    }
    auto canvasMedium = context.createBuffer(pixels * 24);
    auto transposedMedium = context.createBuffer(pixels * 24);
    auto beyond = context.createBuffer(pixels * 12);
    auto fluence = context.createBuffer(pixels * 12);
    auto nearLights = context.createBuffer(mask.bytes().size());
    for (auto* b : {&canvasMedium, &transposedMedium, &beyond, &fluence, &nearLights}) {
        if (!*b) return b->error();
    }
    if (Status s = context.upload(**nearLights, std::as_bytes(mask.bytes())); !s) {
        return s.error();
    }
    {
        // The rows are packed straight into the staging memory (in parallel) and the columns
        // copied from them on the GPU: the medium crosses to the device once.
        Stopwatch upload;
        if (Status s = context.uploadWith(
                **canvasMedium, pixels * sizeof(shared::MediumTexel),
                [&](std::span<std::byte> mapped) {
                    packMediumForGpu(
                        medium,
                        std::span(reinterpret_cast<shared::MediumTexel*>(mapped.data()), pixels));
                });
            !s) {
            return s.error();
        }
        if (Status s = context.fill(**beyond); !s) return s.error();
        record("upload canvas media (CPU)", upload.milliseconds());
        const gpu::Dispatch columns =
            makeTransposeDispatch(*transpose, canvasMedium->get(), transposedMedium->get(), w, h);
        auto ran = context.run(std::span<const gpu::Dispatch>(&columns, 1));
        if (!ran) return ran.error();
        if (timings) timings->insert(timings->end(), ran->begin(), ran->end());
    }

    auto traceMedium = [&](const FrustumFrame& frame) {
        return traceReadsTransposed(frame) ? transposedMedium->get() : canvasMedium->get();
    };
    const Rgb sky = medium.boundaryRadiance;
    int frustums = 0;
    for (int r = 0; r < 4; ++r) {
        if (!(options.frustumMask & (1u << r))) continue;
        ++frustums;
        const FrustumFrame frame = makeFrame(static_cast<Frustum>(r), w, h);
        const int levels = cascadeCount(frame.length);
        std::vector<gpu::Dispatch> passes;
        const std::string tag = " f" + std::to_string(r);
        for (int n = 0; n < levels; ++n) {
            const int planes = planeCount(frame.length, n);
            passes.push_back(
                n < options.tracedLevels
                    ? makeTraceDispatch(*trace, traceMedium(frame), tables[n].get(), n, frame,
                                        planes,
                                        shared::hrcTracedDepthScale(n, options.tracedLevels))
                    : makeExtendDispatch(*extend, tables[n - 1].get(), tables[n].get(), n,
                                         frame.rows, planeCount(frame.length, n - 1), planes));
            passes.back().name += tag;
        }
        int current = 0;
        for (int n = levels - 1; n >= 0; --n) {
            const bool top = n == levels - 1;
            passes.push_back(makeMergeDispatch(
                *merge, tables[n].get(), top ? nullptr : cones[current ^ 1].get(),
                cones[current].get(), weights[n].get(), nearLights->get(), n, frame,
                planeCount(frame.length, n), top ? 0 : planeCount(frame.length, n + 1), sky));
            passes.back().name += tag;
            current ^= 1;
        }
        passes.push_back(
            makeReadoutDispatch(*readout, cones[current ^ 1].get(), beyond->get(), frame, sky));
        passes.back().name += tag;
        auto ran = context.run(passes);
        if (!ran) return ran.error();
        if (timings) timings->insert(timings->end(), ran->begin(), ran->end());
        if (options.onProgress)
            options.onProgress(frustums, std::popcount(options.frustumMask & 0xFu));
    }

    std::vector<gpu::Dispatch> last = {makeFinishDispatch(*finish, canvasMedium->get(),
                                                          beyond->get(), fluence->get(), w, h,
                                                          frustums, options.crossBlur)};
    std::shared_ptr<gpu::Buffer> nearPixels;
    if (!nearField.empty()) {
        auto b = context.createBuffer(nearField.pixels.size() * 4);
        if (!b) return b.error();
        nearPixels = *b;
        if (Status s = context.upload(*nearPixels, std::as_bytes(std::span(nearField.pixels)));
            !s) {
            return s.error();
        }
        last.push_back(makeNearFieldDispatch(
            *nearFieldPass, canvasMedium->get(), nearPixels.get(), fluence->get(), w, h,
            static_cast<std::uint32_t>(nearField.pixels.size()), sky, nearField.reach));
    }
    auto ran = context.run(last);
    if (!ran) return ran.error();
    if (timings) timings->insert(timings->end(), ran->begin(), ran->end());

    Image result(w, h, 3);
    Stopwatch download;
    if (Status s = context.download(
            **fluence, std::as_writable_bytes(std::span(result.data(), result.size())));
        !s) {
        return s.error();
    }
    record("download fluence (CPU)", download.milliseconds());
    return result;
}

}  // namespace

Result<Image> solveHrcOnGpu(gpu::Context& context, const Medium2D& medium,
                            const HrcOptions& options, std::vector<gpu::PassTiming>* timings) {
    const int w = medium.width(), h = medium.height();
    if (options.tracedLevels < 1) {
        return Error("HRC traced levels must be >= 1, got " + std::to_string(options.tracedLevels));
    }
    if ((options.frustumMask & 0xFu) == 0) return Error("HRC frustum mask selects no frustum");
    if (options.debugCascade >= 0)
        return Error("the HRC cascade view runs on the CPU backend only");
    const std::uint64_t needed = estimateHrcGpuMemory(w, h);
    if (context.device().deviceLocalBytes > 0 && needed > context.device().deviceLocalBytes) {
        return Error("HRC at " + std::to_string(w) + "x" + std::to_string(h) + " needs " +
                     formatBytes(needed) + " of device memory, the device has " +
                     formatBytes(context.device().deviceLocalBytes));
    }
    auto record = [&](const std::string& name, double ms) {
        if (timings) timings->push_back({name, ms});
    };
    // The light scores once on the CPU, as solveHrc makes them (§12.3, §12.5).
    const bool splitting =
        options.exactDirectLight && std::popcount(options.frustumMask & 0xFu) == 4;
    Result<LightScores> checkedScores = LightScores::checkedOf(medium, splitting);
    if (!checkedScores) return checkedScores.error();
    LightScores scores = std::move(*checkedScores);
    // §12.5: the compact lights' direct light on the CPU, as solveHrc does; the GPU solves the
    // medium without their emission and the two are summed after the read-back.
    if (splitting) {
        std::optional<Result<Image>> solved = solveSplittingDirectLight(
            medium, scores, options,
            [&](const Medium2D& rest, LightScores& restScores, const HrcOptions& o) {
                return solveCascadesOnGpu(context, rest, restScores, o, timings);
            },
            [&](const DirectLightSplit& s) { record("direct light (cpu)", s.milliseconds); });
        if (solved) return std::move(*solved);
    }
    return solveCascadesOnGpu(context, medium, scores, options, timings);
}

}  // namespace luxel::gi2d
