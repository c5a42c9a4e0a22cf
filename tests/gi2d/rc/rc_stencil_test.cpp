// The stencil-walk RC pass (src/gi2d/rc/rc_stencil.h) against the exact pass it replaces on the
// pixel medium (cascadePass over RayMarcher), cascade by cascade, each level fed the exact upper
// cascade: the same intervals to float rounding on shipped and random media, jittered grids,
// coloured absorption, emitters on the border, non-square canvases and both merges
// (docs/algorithms/radiance-cascades-2d.md §8).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gi2d/rc/rc_cascade_pass.h"
#include "gi2d/rc/rc_stencil.h"
#include "gi2d/rc/stencil_vs_exact.h"
#include "gi2d/shipped_scenes.h"
#include "gpu/random_medium.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::gi2d::rc {
namespace {

// Opaque walls touching the border, a coloured fog, emitters on the canvas edge and a sky.
Medium2D borderMedium(int w, int h) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb(0.2f, 0.3f, 0.5f)};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            Rgb sigma(0.02f, 0.05f, 0.01f), emission;
            if (x == 0 || y == h - 1) emission = Rgb(3.0f, 1.0f, 0.2f), sigma = Rgb(2.0f);
            if (x == w / 3 && y > h / 4) sigma = Rgb(64.0f);  // a wall down to the border
            if (y == h / 2 && x > w / 2) sigma = Rgb(64.0f), emission = Rgb(0.0f, 2.0f, 0.0f);
            m.absorption.setRgb(x, y, sigma);
            m.emission.setRgb(x, y, emission);
        }
    }
    return m;
}

struct Case {
    std::string name;
    Medium2D medium;
};

std::vector<Case> media() {
    std::vector<Case> out;
    out.push_back({"room 120x88", testing_support::shippedScene("room.json", 120, 88)});
    out.push_back({"neon-fog 72x96", testing_support::shippedScene("neon-fog.json", 72, 96)});
    out.push_back({"random 67x45", testing::randomMedium(67, 45, 11, Rgb(0.3f, 0.2f, 0.1f))});
    out.push_back({"border 80x61", borderMedium(80, 61)});
    return out;
}

std::vector<std::pair<std::string, RcOptions>> optionSets() {
    std::vector<std::pair<std::string, RcOptions>> out;
    out.push_back({"default", RcOptions{}});
    RcOptions o;
    o.jitterX = 0.5, o.jitterY = 0.5;
    out.push_back({"jitter 0.5", o});
    o.jitterX = 0.2548776662466927, o.jitterY = 0.8196805819961064;
    out.push_back({"jitter R2", o});
    o = RcOptions{};
    o.probeSpacing = 3, o.baseRays = 8, o.baseInterval = 2.5;
    out.push_back({"spacing 3, 8 rays", o});
    o = RcOptions{};
    o.baseRays = 2, o.maxCascades = 3, o.jitterX = 0.5, o.jitterY = 0.25;
    out.push_back({"2 rays (axis-aligned)", o});
    o = RcOptions{};  // the upper cascades' planes would be large: the marcher serves them
    o.probeSpacing = 48, o.baseRays = 3, o.jitterX = 0.7, o.jitterY = 0.1;
    out.push_back({"spacing 48", o});
    return out;
}

TEST(RcStencil, MatchesTheExactPassAtEveryLevel) {
    for (const Case& m : media()) {
        for (const auto& [optionsName, options] : optionSets()) {
            expectStencilMatchesExact(m.medium, options, m.name + ", " + optionsName);
        }
    }
}

// The whole solve: solveRc (stencil walks) against the exact passes top-down.
TEST(RcStencil, SolveMatchesTheExactSolve) {
    const Medium2D medium = testing_support::shippedScene("room.json", 96, 128);
    const RayMarcher marcher(medium);
    for (RcMerge merge : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
        RcOptions options;
        options.merge = merge;
        options.jitters = 2;
        const Image fast = solveRc(medium, options).value();
        Image exact;
        for (int r = 0; r < options.jitters; ++r) {
            RcOptions one = options;
            one.jitters = 1;
            rcJitterShift(r, one.jitterX, one.jitterY);
            const std::vector<RcCascade> cascades = rcCascades(96, 128, one);
            std::vector<Rgb> upper;
            for (int i = static_cast<int>(cascades.size()) - 1; i >= 0; --i) {
                upper = cascadePass(marcher, cascades, i, upper, medium.boundaryRadiance, merge);
            }
            const Image f = readOut(cascades[0], 0, upper, 96, 128, false);
            if (r == 0) {
                exact = f;
            } else {
                for (std::size_t v = 0; v < exact.size(); ++v) exact.data()[v] += f.data()[v];
            }
        }
        for (std::size_t v = 0; v < exact.size(); ++v) exact.data()[v] *= 0.5f;
        double sum = 0, worst = 0;
        for (std::size_t v = 0; v < exact.size(); ++v) {
            sum += std::abs(exact.data()[v]);
            worst =
                std::max(worst, static_cast<double>(std::abs(fast.data()[v] - exact.data()[v])));
        }
        const double mean = sum / static_cast<double>(exact.size());
        std::printf("%s: max diff %.2e of the mean\n",
                    merge == RcMerge::Vanilla ? "vanilla" : "fix", worst / mean);
        EXPECT_LT(worst, 1e-4 * mean);
    }
}

}  // namespace
}  // namespace luxel::gi2d::rc
