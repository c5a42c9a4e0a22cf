// Coverage of an output pixel by an analytic shape, shared by the rasteriser and the emitter power
// estimate (docs/algorithms/pixel-medium.md §1 and §4).
#pragma once

#include <algorithm>
#include <cmath>

#include "gi2d/shape_geometry.h"

namespace luxel::gi2d::detail {

// Output pixels per scene pixel along each axis.
struct PixelScale {
    PixelScale() = default;
    PixelScale(double x, double y)
        : sx(x), sy(y), halfDiagonal(0.5 * std::hypot(1.0 / x, 1.0 / y)) {}

    Vec2d toScene(double px, double py) const { return {px / sx, py / sy}; }

    double sx = 1, sy = 1;
    // Half the pixel diagonal in scene units: farther than this from an edge, coverage is 0 or 1.
    double halfDiagonal = 0.5 * std::sqrt(2.0);
};

// Fraction of output pixel (x, y) inside `geometry`: exact 0 or 1 away from edges (distance field),
// n x n samples near them.
inline float pixelCoverage(const Geometry& geometry, const PixelScale& scale, int x, int y, int n) {
    const double d = signedDistance(geometry, scale.toScene(x + 0.5, y + 0.5));
    if (d > scale.halfDiagonal) return 0.0f;
    if (d < -scale.halfDiagonal) return 1.0f;
    int inside = 0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            inside +=
                contains(geometry, scale.toScene(x + (i + 0.5) / n, y + (j + 0.5) / n)) ? 1 : 0;
        }
    }
    return static_cast<float>(inside) / static_cast<float>(n * n);
}

// Opaque shapes that do not emit and are thinner than this (output pixels) get the thin-feature
// rule below.
inline constexpr double kThinFeature = 2.5;
// Coverage gain of the thin-feature rule.
inline constexpr float kThinCoverageGain = 4.0f;

// Whether the shape is thinner than kThinFeature around output pixel (x, y): no point of a 9 x 9
// grid spanning 4 px around the pixel lies deeper than kThinFeature / 2 inside it. The grid
// reaches past an edge pixel (whose centre may lie 0.7 px outside) to the middle of a wall of
// 2.5 px, and from the pixels beside a slit into the thick wall around it.
inline bool thinAround(const Geometry& geometry, const PixelScale& scale, int x, int y) {
    const double toOutput = std::min(scale.sx, scale.sy);
    for (int j = -4; j <= 4; ++j) {
        for (int i = -4; i <= 4; ++i) {
            const Vec2d p = scale.toScene(x + 0.5 + 0.5 * i, y + 0.5 + 0.5 * j);
            if (-signedDistance(geometry, p) * toOutput >= 0.5 * kThinFeature) return false;
        }
    }
    return true;
}

// The coverage a pixel is drawn with (docs/algorithms/pixel-medium.md §1, §5). For an opaque
// shape that does not emit, a partly covered pixel where the shape is thin counts
// kThinCoverageGain times its coverage (at most 1): two half-covered pixels of a 1 px wall that
// straddles them would otherwise each transmit half, while with the gain at least one pixel along
// every ray across the wall is opaque. Emitters keep plain coverage (and §4's power), so that a
// small light moving by a fraction of a pixel changes its pixels smoothly.
inline float drawnCoverage(const Geometry& geometry, bool thinRule, const PixelScale& scale, int x,
                           int y, int n) {
    const float c = pixelCoverage(geometry, scale, x, y, n);
    if (!thinRule || c <= 0.0f || c >= 1.0f || !thinAround(geometry, scale, x, y)) return c;
    return std::min(1.0f, kThinCoverageGain * c);
}

}  // namespace luxel::gi2d::detail
