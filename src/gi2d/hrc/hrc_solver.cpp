// HRC driver: per frustum, trace + extend the ray tables, merge cones top-down, read out; then
// the opacity-gated cross blur (docs/algorithms/holographic-radiance-cascades.md §7).
#include "luxel/gi2d/hrc_solver.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/ray_tables.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {

using namespace hrc;

namespace {

constexpr float kQuarterTurn = static_cast<float>(std::numbers::pi / 2.0);

// The pixel's own half-pixel segment towards the frustum
// (docs/algorithms/holographic-radiance-cascades.md §6.2, as in amitabha): the read-out plane is
// one pixel ahead, so this is what lies between the pixel centre and it.
Interval ownHalfPixel(const Medium2D& medium, int x, int y) {
    Interval own;
    const Rgb sigma = medium.absorption.rgb(x, y), emission = medium.emission.rgb(x, y);
    for (int c = 0; c < 3; ++c) {
        const float t = std::exp(-0.5f * sigma[c]);
        own.radiance[c] = emission[c] * (1.0f - t);
        own.transmittance[c] = t;
    }
    return own;
}

// Adds this frustum's angular fluence arriving at every pixel's read-out plane: the merged cones
// of cascade `level` at the first plane beyond the pixel. The pixel's own half-pixel segment is
// the same for every frustum and is applied once at the end.
void readOut(const FrustumFrame& frame, const ConeBuffer& cones, int level, Rgb sky,
             Image& beyondSum) {
    const float coneWidthSum = kQuarterTurn;  // the cones of one probe cover 90 degrees
    parallelForRange(frame.rows, 8, [&](int begin, int end) {
        for (int v = begin; v < end; ++v) {
            for (int u = 0; u < frame.length; ++u) {
                int x, y;
                frame.toCanvas(u, v, x, y);
                const int plane = (u + 1 + pow2(level) - 1) >> level;  // first plane >= u + 1
                Rgb beyond;
                if (cones.inRange(plane, v)) {
                    for (int i = 0; i < cones.cones(); ++i) beyond += cones.at(plane, i, v);
                } else {
                    beyond = sky * coneWidthSum;
                }
                beyondSum.setRgb(x, y, beyondSum.rgb(x, y) + beyond);
            }
        }
    });
}

// Paper Eq 21: 1-px cross blur, centre weight 4, neighbours 1, a neighbour skipped when its
// opacity differs from the centre's by more than 0.1 (weights renormalised). Applied to the light
// arriving at the read-out planes, where the row-parity checkerboard lives, before the pixel's own
// segment: blurring own emission would smear an emitter into the opaque wall next to it.
Image crossBlur(const Medium2D& medium, const Image& fluence) {
    const int w = fluence.width(), h = fluence.height();
    auto opacity = [&](int x, int y) {
        return 1.0f - std::exp(-medium.absorption.rgb(x, y).maxComponent());
    };
    Image out(w, h, 3);
    parallelForRange(h, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                const float centre = opacity(x, y);
                Rgb sum = fluence.rgb(x, y) * 4.0f;
                float weight = 4.0f;
                const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
                for (int t = 0; t < 4; ++t) {
                    if (!fluence.inside(nx[t], ny[t])) continue;
                    if (std::abs(opacity(nx[t], ny[t]) - centre) > 0.1f) continue;
                    sum += fluence.rgb(nx[t], ny[t]);
                    weight += 1.0f;
                }
                out.setRgb(x, y, sum * (1.0f / weight));
            }
        }
    });
    return out;
}

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

    if (options.crossBlur && options.debugCascade < 0) fluence = crossBlur(medium, fluence);
    // Through the pixel's own half-pixel segment, then angular fluence summed over frustums ->
    // mean radiance over directions.
    const float ownWidth = kQuarterTurn * static_cast<float>(frustums);
    const float toMean = static_cast<float>(1.0 / (2.0 * std::numbers::pi));
    parallelForRange(h, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                const Interval own = ownHalfPixel(medium, x, y);
                const Rgb total = own.radiance * ownWidth + own.transmittance * fluence.rgb(x, y);
                fluence.setRgb(x, y, total * toMean);
            }
        }
    });
    return fluence;
}

}  // namespace luxel::gi2d
