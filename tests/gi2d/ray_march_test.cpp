// Exact DDA integration: segment lengths, compositing, edge cases of direction and start point.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {
namespace {

Medium2D uniformMedium(int w, int h, Rgb emission, Rgb sigma) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb()};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            m.emission.setRgb(x, y, emission);
            m.absorption.setRgb(x, y, sigma);
        }
    }
    return m;
}

TEST(RayMarch, UniformFogMatchesClosedFormAlongAnyDirection) {
    // In a uniform medium L = E (1 - exp(-sigma d)) and T = exp(-sigma d) for the path length d.
    const Rgb e(2.0f, 1.0f, 0.5f), s(0.01f, 0.02f, 0.04f);
    const Medium2D m = uniformMedium(64, 48, e, s);
    const RayMarcher marcher(m);
    for (double angleDeg : {0.0, 17.0, 45.0, 90.0, 133.0, 180.0, 225.0, 300.0}) {
        const double a = angleDeg * std::numbers::pi / 180.0;
        const Vec2d dir{std::cos(a), std::sin(a)};
        const Vec2d origin{20.5, 20.5};
        const double d = 10.0;
        const RaySegment seg = marcher.march(origin, dir, d);
        for (int c = 0; c < 3; ++c) {
            const double t = std::exp(-s[c] * d);
            EXPECT_NEAR(seg.transmittance[c], t, 1e-5) << angleDeg;
            EXPECT_NEAR(seg.radiance[c], e[c] * (1 - t), 1e-5) << angleDeg;
        }
    }
}

TEST(RayMarch, PathLengthToCanvasEdgeIsExactOnDiagonals) {
    const float sigma = 0.05f;
    const Medium2D m = uniformMedium(32, 32, Rgb(0.0f), Rgb(sigma));
    const RayMarcher marcher(m);
    // From the centre of pixel (3, 5) along (1, 1)/sqrt2 the ray leaves through x = 32 after
    // (32 - 3.5) * sqrt2... or y = 32 after (32 - 5.5) * sqrt2: the earlier one.
    const double s2 = std::sqrt(0.5);
    const RaySegment seg = marcher.march({3.5, 5.5}, {s2, s2});
    const double d = (32.0 - 5.5) * std::sqrt(2.0);
    EXPECT_NEAR(seg.transmittance.r, std::exp(-sigma * d), 1e-5);
}

TEST(RayMarch, ZeroAndNegativeZeroDirectionComponentsAgree) {
    Medium2D m = uniformMedium(16, 16, Rgb(0.0f), Rgb(0.1f));
    m.emission.setRgb(15, 8, Rgb(1.0f));
    m.absorption.setRgb(15, 8, Rgb(50.0f));
    const RayMarcher marcher(m);
    const RaySegment a = marcher.march({2.5, 8.5}, {1.0, 0.0});
    const RaySegment b = marcher.march({2.5, 8.5}, {1.0, -0.0});
    EXPECT_EQ(a.radiance, b.radiance);
    EXPECT_EQ(a.transmittance, b.transmittance);
    // 12 px of fog (from x = 2.5 to 15) then the opaque emitter.
    EXPECT_NEAR(a.radiance.r, std::exp(-0.1 * 12.5), 1e-5);
}

TEST(RayMarch, RayAlongACellBorderSeesTheCellsItTouches) {
    // A ray exactly on the line y = 8 (a pixel border) moving along +x: cells of row 8 are used,
    // consistently, and the result is finite.
    Medium2D m = uniformMedium(16, 16, Rgb(0.0f), Rgb(0.0f));
    const RayMarcher marcher(m);
    const RaySegment seg = marcher.march({0.0, 8.0}, {1.0, 0.0});
    EXPECT_EQ(seg.transmittance, Rgb(1.0f));
    // Starting exactly on the right border and leaving: nothing crossed.
    const RaySegment out = marcher.march({16.0, 4.5}, {1.0, 0.0});
    EXPECT_EQ(out.transmittance, Rgb(1.0f));
}

TEST(RayMarch, ARayThroughABlockCornerKeepsGoing) {
    // The ray reaches the corner (12, 3) where rounding puts x just below 12 and y just above 3;
    // the DDA once stepped back and forth between (12, 3) and the vacuum block left of it forever.
    Medium2D m = uniformMedium(50, 70, Rgb(), Rgb());
    m.absorption.setRgb(12, 3, {1.0f, 1.0f, 1.0f});
    const RayMarcher marcher(m);
    const double len = std::hypot(16.0, 6.0);
    const RaySegment s = marcher.march({0.0, 7.5}, {16.0 / len, -6.0 / len}, len, 0.0f);
    // The ray touches (12, 3) only at its corner, and leaves through the bottom edge.
    EXPECT_FLOAT_EQ(s.transmittance.r, 1.0f);
}

TEST(RayMarch, BoundaryRadianceArrivesThroughTheMedium) {
    Medium2D m = uniformMedium(20, 10, Rgb(0.0f), Rgb(0.1f));
    m.boundaryRadiance = Rgb(3.0f);
    const RayMarcher marcher(m);
    const RaySegment seg = marcher.march({10.5, 5.5}, {-1.0, 0.0});
    EXPECT_NEAR(seg.radiance.r, 3.0 * std::exp(-0.1 * 10.5), 1e-5);
    // Stopping before the border: no boundary light.
    EXPECT_NEAR(marcher.march({10.5, 5.5}, {-1.0, 0.0}, 5.0).radiance.r, 0.0, 1e-7);
}

TEST(RayMarch, BlockSkippingGivesTheSameAnswerAsPlainCellSteps) {
    // A medium with sparse features: the block quadtree crosses empty regions in one step. The
    // answer must equal a brute-force march with tiny uniform steps (midpoint rule, exact for
    // piecewise-constant media up to the step size).
    const int w = 128, h = 96;
    Medium2D m = uniformMedium(w, h, Rgb(0.0f), Rgb(0.002f));
    for (int y = 40; y < 44; ++y) {
        for (int x = 70; x < 75; ++x) {
            m.emission.setRgb(x, y, Rgb(4.0f, 2.0f, 1.0f));
            m.absorption.setRgb(x, y, Rgb(0.5f, 1.0f, 2.0f));
        }
    }
    m.absorption.setRgb(30, 60, Rgb(3.0f));
    const RayMarcher marcher(m);
    for (int i = 0; i < 64; ++i) {
        const double a = 2.0 * std::numbers::pi * (i + 0.37) / 64.0;
        const Vec2d dir{std::cos(a), std::sin(a)}, origin{40.3, 50.7};
        const RaySegment fast = marcher.march(origin, dir);
        double L[3] = {0, 0, 0}, T[3] = {1, 1, 1};
        const double step = 1e-3;
        for (double t = step * 0.5;; t += step) {
            const Vec2d p = origin + dir * t;
            if (p.x < 0 || p.y < 0 || p.x >= w || p.y >= h) break;
            const int cx = static_cast<int>(p.x), cy = static_cast<int>(p.y);
            for (int c = 0; c < 3; ++c) {
                const double tr = std::exp(-m.absorption.at(cx, cy, c) * step);
                L[c] += T[c] * m.emission.at(cx, cy, c) * (1 - tr);
                T[c] *= tr;
            }
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(fast.radiance[c], L[c], 2e-3 * (L[c] + 1e-3)) << "ray " << i;
            EXPECT_NEAR(fast.transmittance[c], T[c], 2e-3) << "ray " << i;
        }
    }
}

}  // namespace
}  // namespace luxel::gi2d
