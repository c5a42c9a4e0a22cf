// Moving-light stability of RC: a small light moved by a fraction of a pixel must not change the
// image where the truth does not change (docs/solver-errors.md, "moving lights").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d {
namespace {

// A small light left of a wall, a static wide light on the right that lights the wall's shadow.
Medium2D movingLightScene(double dx) {
    Scene2D scene{128, 128, {}, {}, {}, ""};
    scene.shapes.push_back({"light", Circle{{30.0 + dx, 40.0 + 0.5 * dx}, 2.5},
                            Material{Rgb(8.0f), Rgb(kOpaqueAbsorption)}});
    scene.shapes.push_back(
        {"static", Box{{120, 64}, {6, 100}, 0.0}, Material{Rgb(1.0f), Rgb(kOpaqueAbsorption)}});
    scene.shapes.push_back(
        {"wall", Box{{60, 64}, {4, 128}, 0.0}, Material{{}, Rgb(kOpaqueAbsorption)}});
    return rasterize(scene).value();
}

double mean(const Image& f) {
    double s = 0;
    for (int y = 0; y < f.height(); ++y)
        for (int x = 0; x < f.width(); ++x) s += f.at(x, y, 0);
    return s / (f.width() * f.height());
}

TEST(RcMovingLight, Explore) {
    ReferenceOptions ro;
    ro.rays = 256;
    for (double step : {0.25, 0.5, 1.0}) {
        const Medium2D a = movingLightScene(0), b = movingLightScene(step);
        const Image ra = solveReference(a, ro).value(), rb = solveReference(b, ro).value();
        const double m = mean(ra);
        for (RcMerge merge : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
            RcOptions o;
            o.merge = merge;
            const Image ca = solveRc(a, o).value(), cb = solveRc(b, o).value();
            double worst = 0, sum = 0, worstRef = 0;
            int n = 0;
            for (int y = 0; y < 128; ++y) {
                for (int x = 0; x < 128; ++x) {
                    if (std::abs(rb.at(x, y, 0) - ra.at(x, y, 0)) >= 1e-3 * m) continue;
                    const double d = std::abs(cb.at(x, y, 0) - ca.at(x, y, 0)) / m;
                    worst = std::max(worst, d);
                    worstRef =
                        std::max(worstRef, double(std::abs(rb.at(x, y, 0) - ra.at(x, y, 0))) / m);
                    sum += d;
                    ++n;
                }
            }
            std::printf(
                "step %.2f %s: stable pixels %d, max change %.4f%% of mean, mean %.5f%% (ref max "
                "%.4f%%)\n",
                step, merge == RcMerge::Vanilla ? "vanilla" : "fix", n, 100 * worst, 100 * sum / n,
                100 * worstRef);
        }
    }
}

}  // namespace
}  // namespace luxel::gi2d
