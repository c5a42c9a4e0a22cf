// HRC driver (docs/algorithms/holographic-radiance-cascades.md §7): per frustum, trace + extend
// the ray tables, merge cones top-down, read out; then finish (cross blur, own segment).
#include "luxel/gi2d/hrc_solver.h"

#include <algorithm>
#include <bit>
#include <string>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/finish.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/ray_tables.h"
#include "gi2d/hrc/readout.h"
#include "luxel/core/memory.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {

using namespace hrc;

namespace {

FrustumFrame frameFor(int r, int w, int h) {
    return makeFrame(static_cast<Frustum>(r), w, h);
}

}  // namespace

int hrcCascadeCount(int width, int height) {
    return std::max(cascadeCount(width), cascadeCount(height));
}

HrcMemory estimateHrcMemory(int width, int height) {
    HrcMemory m;
    for (int r = 0; r < 2; ++r) {
        const FrustumFrame f = frameFor(r, width, height);
        const int levels = cascadeCount(f.length);
        m.rayTables = std::max(m.rayTables, RayTables::bytesFor(f.length, f.rows, levels));
        std::uint64_t cones = 0;
        for (int n = 0; n < levels; ++n) {
            cones = std::max<std::uint64_t>(
                cones, static_cast<std::uint64_t>(planeCount(f.length, n)) * pow2(n) * f.rows);
        }
        m.coneBuffers = std::max(m.coneBuffers, 2 * cones * sizeof(Rgb));
    }
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    // The rotated medium lives while its marcher is built; the marcher lives for the frustum.
    m.frame = mediumBytes(width, height) + RayMarcher::bytesFor(width, height);
    m.output = 2 * pixels * 3 * sizeof(float);  // accumulator + blurred copy
    return m;
}

Result<Image> solveHrc(const Medium2D& medium, const HrcOptions& options) {
    const int w = medium.width(), h = medium.height();
    if (options.tracedLevels < 1) {
        return Error("HRC traced levels must be >= 1, got " + std::to_string(options.tracedLevels));
    }
    if ((options.frustumMask & 0xFu) == 0) return Error("HRC frustum mask selects no frustum");
    if (static_cast<std::uint64_t>(w) * h > RayMarcher::kMaxPixels) {
        return Error("HRC supports at most 2^28 pixels, got " + std::to_string(w) + "x" +
                     std::to_string(h));
    }
    if (Status s = checkMemory(estimateHrcMemory(w, h).total(),
                               "HRC at " + std::to_string(w) + "x" + std::to_string(h));
        !s) {
        return s.error();
    }

    Image fluence(w, h, 3);
    RayTables tables;
    ConeBuffer buffers[2];
    const int frustums = std::popcount(options.frustumMask & 0xFu);
    int done = 0;
    for (int r = 0; r < 4; ++r) {
        if (!(options.frustumMask & (1u << r))) continue;
        const FrustumFrame frame = frameFor(r, w, h);
        const int levels = cascadeCount(frame.length);
        if (options.debugCascade >= levels) {
            return Error("debug cascade " + std::to_string(options.debugCascade) +
                         " does not exist (this size has " + std::to_string(levels) + ")");
        }
        {
            const RayMarcher marcher(frameMedium(medium, frame));
            tables.reset(frame.length, frame.rows, levels);
            traceBaseLevels(tables, marcher, options.tracedLevels);
        }
        extendLevels(tables, options.tracedLevels);

        const int lowest = std::max(options.debugCascade, 0);
        const ConeBuffer* upper = nullptr;
        int current = 0;
        for (int n = levels - 1; n >= lowest; --n) {
            mergeCascade(tables, n, upper, medium.boundaryRadiance, buffers[current]);
            upper = &buffers[current];
            current ^= 1;
        }
        readOut(frame, *upper, lowest, medium.boundaryRadiance, fluence);
        if (options.onProgress) options.onProgress(++done, frustums);
    }

    return finishFluence(medium, fluence, frustums, options.crossBlur && options.debugCascade < 0);
}

}  // namespace luxel::gi2d
