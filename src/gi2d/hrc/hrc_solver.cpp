// HRC driver (docs/algorithms/holographic-radiance-cascades.md §7): the frustums swept one after
// another (§7.1), or cascade by cascade for the debug views; then finish (cross blur, own
// segment).
#include "luxel/gi2d/hrc_solver.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <string>
#include <utility>

#include "gi2d/hrc/direct_light.h"
#include "gi2d/hrc/finish.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/level_by_level.h"
#include "gi2d/hrc/light_scores.h"
#include "gi2d/hrc/near_field.h"
#include "gi2d/hrc/near_lights.h"
#include "gi2d/hrc/sweep_solver.h"
#include "luxel/core/memory.h"
#include "luxel/core/thread_team.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {

using namespace hrc;

int hrcCascadeCount(int width, int height) {
    return std::max(cascadeCount(width), cascadeCount(height));
}

HrcMemory estimateHrcMemory(int width, int height) {
    const SweepMemory sweep =
        sweepMemory(width, height, HrcOptions{}.tracedLevels, ThreadTeam::defaultSize());
    HrcMemory m;
    m.rayIntervals = sweep.intervals;
    m.cones = sweep.cones;
    m.mediumColumns = sweep.columns;
    m.nearLights = sweep.nearLights;
    m.output = static_cast<std::uint64_t>(width) * height * 3 * sizeof(float);
    return m;
}

namespace {

// solveHrc without the split of §12.5, on a medium whose light scores are `scores`: they make the
// near field's plan and the near-light mask, then are freed before the sweep allocates its rings.
Result<Image> solveCascades(const Medium2D& medium, LightScores& scores, const HrcOptions& options,
                            std::vector<HrcCpuPass>* passes) {
    const int w = medium.width(), h = medium.height();
    const bool debug = options.debugCascade >= 0;
    // The sweep's medium window grows with 2^tracedLevels times the distinct lengths inside cells
    // (3 for the paper's 3 traced cascades): many traced cascades go cascade by cascade instead.
    const int frustums = std::popcount(options.frustumMask & 0xFu);
    const bool levelByLevel = debug || options.tracedLevels > kSweepMaxTracedLevels;
    // The exact near field of §12.3 after the finish, for the whole fluence only.
    const NearFieldPlan nearField =
        options.exactNearField && !debug && frustums == 4 ? planNearField(scores) : NearFieldPlan{};
    const std::uint64_t needed =
        (nearField.empty() ? 0 : RayMarcher::bytesFor(w, h)) +
        (levelByLevel ? levelByLevelBytes(w, h) + mediumBytes(w, h) / 2
                      : sweepMemory(w, h, options.tracedLevels, ThreadTeam::defaultSize()).total() +
                            estimateHrcMemory(w, h).output);
    if (Status s = checkMemory(needed, "HRC at " + std::to_string(w) + "x" + std::to_string(h));
        !s) {
        return s.error();
    }

    if (levelByLevel) {
        if (passes != nullptr) passes->clear();
        const NearLightMask mask = NearLightMask::fromScores(scores);
        scores.release();
        Image beyond = levelByLevelBeyond(medium, options, mask);
        finishFluenceInPlace(medium, beyond, frustums, options.crossBlur && !debug);
        gatherNearFieldInPlace(medium, nearField, beyond);
        return beyond;
    }
    SweepTimes times;
    Image beyond(w, h, 3);
    sweepFrustums(medium, std::move(scores), options, ThreadTeam::defaultSize(), beyond,
                  passes != nullptr ? &times : nullptr);
    const auto start = std::chrono::steady_clock::now();
    finishFluenceInPlace(medium, beyond, frustums, options.crossBlur);
    if (passes != nullptr) {
        const char* names[] = {"trace", "extend", "merge", "readout"};
        passes->clear();
        for (int p = 0; p < SweepTimes::Count; ++p) {
            passes->push_back({names[p], times.milliseconds[p], times.bytes[p]});
        }
        const std::uint64_t pixels = static_cast<std::uint64_t>(w) * h;
        passes->push_back(
            {"finish",
             std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                 .count(),
             pixels * (24 + 12 + 12 + 12)});
    }
    if (!nearField.empty()) {
        const auto gather = std::chrono::steady_clock::now();
        gatherNearFieldInPlace(medium, nearField, beyond);
        if (passes != nullptr) {
            passes->push_back({"near field",
                               std::chrono::duration<double, std::milli>(
                                   std::chrono::steady_clock::now() - gather)
                                   .count(),
                               0});
        }
    }
    return beyond;
}

}  // namespace

Result<Image> solveHrc(const Medium2D& medium, const HrcOptions& options,
                       std::vector<HrcCpuPass>* passes) {
    const int w = medium.width(), h = medium.height();
    if (options.tracedLevels < 1) {
        return Error("HRC traced levels must be >= 1, got " + std::to_string(options.tracedLevels));
    }
    if ((options.frustumMask & 0xFu) == 0) return Error("HRC frustum mask selects no frustum");
    if (static_cast<std::uint64_t>(w) * h > RayMarcher::kMaxPixels) {
        return Error("HRC supports at most 2^28 pixels, got " + std::to_string(w) + "x" +
                     std::to_string(h));
    }
    const bool debug = options.debugCascade >= 0;
    for (int r = 0; r < 4 && debug; ++r) {
        if (!(options.frustumMask & (1u << r))) continue;
        const int levels = cascadeCount(makeFrame(static_cast<Frustum>(r), w, h).length);
        if (options.debugCascade >= levels) {
            return Error("debug cascade " + std::to_string(options.debugCascade) +
                         " does not exist (this size has " + std::to_string(levels) + ")");
        }
    }
    // The light scores, once for the compact lights' search, the near-light mask and the near
    // field's plan (§12.3, §12.5); the first of the solve's buffers.
    const bool splitting =
        options.exactDirectLight && !debug && std::popcount(options.frustumMask & 0xFu) == 4;
    Result<LightScores> checkedScores = LightScores::checkedOf(medium, splitting);
    if (!checkedScores) return checkedScores.error();
    LightScores scores = std::move(*checkedScores);
    // §12.5: the compact lights' direct light exactly, the cascades on the rest of the emission.
    if (splitting) {
        DirectLightSplit split;
        std::optional<Result<Image>> solved = solveSplittingDirectLight(
            medium, scores, options,
            [passes](const Medium2D& rest, LightScores& restScores, const HrcOptions& o) {
                return solveCascades(rest, restScores, o, passes);
            },
            [&split](const DirectLightSplit& s) { split = s; });
        if (solved) {
            // After the rest's solve, which begins the pass list anew.
            if (*solved && passes != nullptr && !passes->empty()) {
                passes->push_back({"direct light", split.milliseconds, split.work * 12});
            }
            return std::move(*solved);
        }
    }
    return solveCascades(medium, scores, options, passes);
}

}  // namespace luxel::gi2d
