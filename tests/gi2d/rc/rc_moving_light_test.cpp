// RC with its default merge where cascades are weakest: a small light moved by a pixel must not
// change the image where the truth does not change, and light must pass thin slits as in the
// truth (docs/solver-errors.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "luxel/core/metrics.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d {
namespace {

// A small light left of a wall; a static light on the right lights the wall's shadow, where the
// truth does not change when the small light moves.
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

double meanRed(const Image& f) {
    double s = 0;
    for (int y = 0; y < f.height(); ++y) {
        for (int x = 0; x < f.width(); ++x) s += f.at(x, y, 0);
    }
    return s / (f.width() * f.height());
}

// How much the solver's image changes (red channel, as a fraction of the truth's mean `m`) where
// the truth changes by less than 0.1% of its mean: at most, and on average over those pixels.
struct StillChange {
    double worst = 0, mean = 0;
    int pixels = 0;
};
StillChange changeWhereTruthIsStill(const Image& truthA, const Image& truthB, const Image& a,
                                    const Image& b, double m) {
    StillChange c;
    double sum = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            if (std::abs(truthB.at(x, y, 0) - truthA.at(x, y, 0)) >= 1e-3 * m) continue;
            const double d = std::abs(b.at(x, y, 0) - a.at(x, y, 0)) / m;
            c.worst = std::max(c.worst, d);
            sum += d;
            ++c.pixels;
        }
    }
    c.mean = c.pixels > 0 ? sum / c.pixels : 0.0;
    return c;
}

TEST(RcMovingLight, DefaultMergeBarelyChangesWhereTheTruthDoesNot) {
    ReferenceOptions ro;
    ro.rays = 256;
    const Medium2D a = movingLightScene(0), b = movingLightScene(1.0);
    const Image ra = solveReference(a, ro).value(), rb = solveReference(b, ro).value();
    const double m = meanRed(ra);
    const Image ca = solveRc(a).value(), cb = solveRc(b).value();  // the default merge
    const StillChange c = changeWhereTruthIsStill(ra, rb, ca, cb, m);
    std::printf(
        "light moved 1 px: %d pixels where the truth changes < 0.1%%; RC changes there by "
        "%.3f%% of the mean at most, %.4f%% on average\n",
        c.pixels, 100 * c.worst, 100 * c.mean);
    ASSERT_GT(c.pixels, 128 * 128 / 2);
    // Measured: vanilla 15.8% at most, 0.068% on average; the bilinear fix 8.7%, 0.028%. The
    // rays are still points: a light between two of them pops (docs/solver-errors.md).
    EXPECT_LT(c.worst, 0.11);
    EXPECT_LT(c.mean, 0.00045);
}

// Two walls 4 px thick, each with a 1.5 px slit off the light's axis; a wide light on the left.
Medium2D slitScene() {
    Scene2D scene{128, 128, {}, {}, {}, ""};
    scene.shapes.push_back(
        {"light", Box{{6, 64}, {8, 100}, 0.0}, Material{Rgb(4.0f), Rgb(kOpaqueAbsorption)}});
    for (double x : {40.0, 80.0}) {
        const double slit = x == 40.0 ? 50.0 : 58.0;
        const double below = slit - 0.75, above = slit + 0.75;
        scene.shapes.push_back(
            {"wall", Box{{x, below / 2}, {4, below}, 0.0}, Material{{}, Rgb(kOpaqueAbsorption)}});
        scene.shapes.push_back({"wall", Box{{x, (above + 128) / 2}, {4, 128 - above}, 0.0},
                                Material{{}, Rgb(kOpaqueAbsorption)}});
    }
    return rasterize(scene).value();
}

double meanBetween(const Image& f, int x0, int x1) {
    double s = 0;
    for (int y = 0; y < f.height(); ++y) {
        for (int x = x0; x < x1; ++x) s += f.at(x, y, 0);
    }
    return s / ((x1 - x0) * f.height());
}

TEST(RcSlits, DefaultMergePassesSlitsNearTheTruth) {
    const Medium2D medium = slitScene();
    ReferenceOptions ro;
    ro.rays = 512;
    const Image truth = solveReference(medium, ro).value();
    RcOptions vanilla;
    vanilla.merge = RcMerge::Vanilla;
    const Image fixed = solveRc(medium).value(), plain = solveRc(medium, vanilla).value();
    for (auto [x0, x1, name] :
         {std::tuple{44, 78, "past the first wall"}, std::tuple{84, 128, "past the second wall"}}) {
        const double t = meanBetween(truth, x0, x1);
        const double f = meanBetween(fixed, x0, x1) / t, v = meanBetween(plain, x0, x1) / t;
        std::printf("%s: reference %.6f; default merge %.3fx, vanilla %.3fx the truth\n", name, t,
                    f, v);
        ASSERT_GT(t, 0.0) << name;
        // Measured past the first wall: the bilinear fix 0.85x; vanilla merges upper probes from
        // the lit side of the wall and reads 3.5x. Past the second (two slits in line) both lose
        // light (fix 0.52x, vanilla 0.26x): too few rays thread both slits; not bounded here.
        if (x0 == 44) {
            EXPECT_NEAR(f, 1.0, 0.25) << name;
        }
    }
}

// Probe-grid jitter (docs/algorithms/radiance-cascades-2d.md §7): 16 solves with the grids above
// cascade 0 shifted by different fractions of their spacing, averaged. The light no longer pops in
// blocks of one grid, and the image is closer to the truth.
TEST(RcMovingLight, JitteredProbeGridsPopLessAndMatchTheTruthBetter) {
    ReferenceOptions ro;
    ro.rays = 1024;  // the truth's noise would decide which pixels count
    const Medium2D a = movingLightScene(0), b = movingLightScene(1.0);
    const Image ra = solveReference(a, ro).value(), rb = solveReference(b, ro).value();
    const double m = meanRed(ra);
    RcOptions plain, jittered;
    jittered.jitters = 16;
    const Image ca = solveRc(a, jittered).value(), cb = solveRc(b, jittered).value();
    const StillChange c = changeWhereTruthIsStill(ra, rb, ca, cb, m);
    const double errorPlain = compareImages(solveRc(a, plain).value(), ra).value().relativeL1;
    const double errorJittered = compareImages(ca, ra).value().relativeL1;
    std::printf(
        "16 jittered grids, light moved 1 px: RC changes by %.3f%% of the mean at most, %.4f%% on "
        "average where the truth does not; rel-L1 against the truth %.4f (one grid %.4f)\n",
        100 * c.worst, 100 * c.mean, errorJittered, errorPlain);
    ASSERT_GT(c.pixels, 128 * 128 / 2);
    // Measured: 2.6% at most, 0.022% on average (one grid: 7.3%, 0.038%); rel-L1 0.019 (0.028).
    EXPECT_LT(c.worst, 0.04);
    EXPECT_LT(c.mean, 0.0003);
    EXPECT_LT(errorJittered, 0.8 * errorPlain);
}

}  // namespace
}  // namespace luxel::gi2d
