// The bounce rule shared by every 2D solver (docs/algorithms/scattering-2d.md).
#include <algorithm>
#include <cmath>

#include "luxel/core/parallel.h"
#include "luxel/gi2d/bounce.h"

namespace luxel::gi2d {

namespace {

// Mean radiance arriving at the opaque pixel (x, y) from outside. A transparent neighbour q of a
// flat wall sees the wall (radiance S_prev) in half its directions and the rest of the scene in
// the other half, so the rest reads 2 fluence_q - S_prev. Neighbours are weighted by their
// transparency over one pixel; the 4-neighbours count twice as much as the diagonals.
Rgb arrivingRadiance(const Medium2D& medium, const Image& fluence, Rgb previous, int x, int y) {
    static constexpr int kOffsets[8][2] = {{1, 0}, {-1, 0}, {0, 1},  {0, -1},
                                           {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
    Rgb sum;
    double weight = 0;
    for (int k = 0; k < 8; ++k) {
        const int qx = x + kOffsets[k][0], qy = y + kOffsets[k][1];
        if (!medium.emission.inside(qx, qy)) continue;
        const Rgb sigma = medium.absorption.rgb(qx, qy);
        const float transparency = std::exp(-(sigma.r + sigma.g + sigma.b) / 3.0f);
        const float w = transparency * (k < 4 ? 1.0f : 0.5f);
        if (w < 1e-4f) continue;
        const Rgb f = fluence.rgb(qx, qy);
        for (int c = 0; c < 3; ++c) sum[c] += w * std::max(0.0f, 2.0f * f[c] - previous[c]);
        weight += w;
    }
    return weight > 0 ? sum * static_cast<float>(1.0 / weight) : Rgb();
}

// Change of the bounced light alone: sum |next - previous| / sum |next - E|. Measured against
// the whole source, a bright light would hide a room that is still filling up.
double bouncedChange(const Image& next, const Image& previous, const Image& emission) {
    double diff = 0, bounced = 0;
    for (std::size_t i = 0; i < next.size(); ++i) {
        diff += std::abs(static_cast<double>(next.data()[i]) - previous.data()[i]);
        bounced += std::abs(static_cast<double>(next.data()[i]) - emission.data()[i]);
    }
    return bounced > 0 ? diff / bounced : 0.0;
}

}  // namespace

Image bounceSource(const Medium2D& medium, const Image& fluence, const Image& previousSource) {
    Image source = medium.emission;
    const bool scatters = !medium.scattering.empty(), reflects = !medium.reflectance.empty();
    parallelForRange(medium.height(), 4, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < medium.width(); ++x) {
                Rgb s = medium.emission.rgb(x, y);
                if (scatters) s += medium.scattering.rgb(x, y) * fluence.rgb(x, y);
                if (reflects) {
                    const Rgb rho = medium.reflectance.rgb(x, y);
                    if (rho.maxComponent() > 0) {
                        s +=
                            rho * arrivingRadiance(medium, fluence, previousSource.rgb(x, y), x, y);
                    }
                }
                source.setRgb(x, y, s);
            }
        }
    });
    return source;
}

Result<BounceResult> solveWithBounces(const Medium2D& medium, const FluenceSolve& solve,
                                      const BounceOptions& options) {
    Medium2D lit = medium;  // the medium with the current source as its emission
    auto fluence = solve(lit);
    if (!fluence) return fluence.error();
    if (options.onSolve) options.onSolve(1, 0.0);
    BounceResult result;
    result.fluence = std::move(*fluence);
    if (!medium.bounces()) {
        result.source = std::move(lit.emission);
        return result;
    }
    for (int k = 0; k < options.maxBounces; ++k) {
        Image next = bounceSource(medium, result.fluence, lit.emission);
        result.change = bouncedChange(next, lit.emission, medium.emission);
        lit.emission = std::move(next);
        auto f = solve(lit);
        if (!f) return f.error();
        result.fluence = std::move(*f);
        result.bounces = k + 1;
        if (options.onSolve) options.onSolve(k + 2, result.change);
        if (options.tolerance > 0 && result.change < options.tolerance) {
            result.converged = true;
            break;
        }
    }
    result.source = std::move(lit.emission);
    return result;
}

Result<BounceResult> solveReferenceWithBounces(const Medium2D& medium,
                                               const ReferenceOptions& reference,
                                               double tolerance) {
    BounceOptions options;
    options.maxBounces = kMaxReferenceBounces;
    options.tolerance = tolerance;
    return solveWithBounces(
        medium, [&](const Medium2D& m) { return solveReference(m, reference); }, options);
}

}  // namespace luxel::gi2d
