// Brute-force reference fluence: stratified jittered directions per pixel, exact DDA marching.
#include "luxel/gi2d/reference_solver.h"

#include <cmath>
#include <numbers>
#include <string>

#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/core/rng.h"

namespace luxel::gi2d {

Rgb referenceFluenceAt(const RayMarcher& marcher, int x, int y, const ReferenceOptions& options) {
    Pcg32 rng(hashSeed(options.seed, static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y)));
    const Vec2d origin{x + 0.5, y + 0.5};
    const double step = 2.0 * std::numbers::pi / options.rays;
    double sum[3] = {0, 0, 0};
    for (int k = 0; k < options.rays; ++k) {
        const double angle = (k + rng.nextDouble()) * step;
        const RaySegment ray = marcher.march(origin, {std::cos(angle), std::sin(angle)}, 1e30,
                                             options.transmittanceCutoff);
        for (int c = 0; c < 3; ++c) sum[c] += ray.radiance[c];
    }
    const double norm = 1.0 / options.rays;
    return {static_cast<float>(sum[0] * norm), static_cast<float>(sum[1] * norm),
            static_cast<float>(sum[2] * norm)};
}

Result<Image> solveReference(const Medium2D& medium, const ReferenceOptions& options) {
    if (options.rays < 1 || options.rays > kMaxReferenceRays) {
        return Error("rays must be in 1.." + std::to_string(kMaxReferenceRays) + ", got " +
                     std::to_string(options.rays));
    }
    const int w = medium.width(), h = medium.height();
    const std::uint64_t bytes = RayMarcher::bytesFor(w, h) + imageBytes(w, h, 3);
    if (Status s = checkMemory(
            bytes, "the reference solver at " + std::to_string(w) + "x" + std::to_string(h));
        !s) {
        return s.error();
    }
    const RayMarcher marcher(medium);
    Image fluence(w, h, 3);
    parallelForRange(h, 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x)
                fluence.setRgb(x, y, referenceFluenceAt(marcher, x, y, options));
            if (options.onRowsDone) options.onRowsDone(1);
        }
    });
    return fluence;
}

}  // namespace luxel::gi2d
