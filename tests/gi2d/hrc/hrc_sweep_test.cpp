// The streaming HRC solver (docs/algorithms/holographic-radiance-cascades.md §7.1) against the
// level-by-level passes it reorders: the same intervals, cones and read-out, so the same image up
// to float rounding, at any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>

#include "gi2d/hrc/finish.h"
#include "gi2d/hrc/level_by_level.h"
#include "gi2d/hrc/trace_stencil.h"
#include "gi2d/shipped_scenes.h"
#include "luxel/core/parallel.h"
#include "luxel/core/rng.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {
namespace {

using testing_support::shippedScene;

Image levelByLevel(const Medium2D& medium, const HrcOptions& options) {
    const int frustums = std::popcount(options.frustumMask & 0xFu);
    return hrc::finishFluence(medium, hrc::levelByLevelBeyond(medium, options), frustums,
                              options.crossBlur);
}

// Largest difference relative to the image's largest value.
double maxRelativeDifference(const Image& a, const Image& b) {
    double most = 0.0, scale = 1e-30;
    for (std::size_t i = 0; i < a.size(); ++i) {
        most = std::max(most, static_cast<double>(std::abs(a.data()[i] - b.data()[i])));
        scale = std::max(scale, static_cast<double>(std::abs(b.data()[i])));
    }
    return most / scale;
}

// Random coloured fog, opaque blocks, emitters touching the border, sky light.
Medium2D randomMedium(int w, int h, std::uint64_t seed) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb{0.2f, 0.1f, 0.05f}};
    Pcg32 rng(seed);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float kind = rng.nextFloat();
            Rgb sigma, emission;
            if (kind < 0.5f) {
                sigma = {};  // vacuum
            } else if (kind < 0.8f) {
                sigma = {0.05f * rng.nextFloat(), 0.1f * rng.nextFloat(), 0.02f};
            } else if (kind < 0.95f) {
                sigma = {40.0f, 40.0f, 40.0f};  // opaque
            } else {
                sigma = {2.0f, 1.0f, 3.0f};
                emission = {5.0f * rng.nextFloat(), 2.0f, 0.5f};
            }
            m.absorption.setRgb(x, y, sigma);
            m.emission.setRgb(x, y, emission);
        }
    }
    return m;
}

TEST(HrcSweep, StencilsCrossTheCellsTheMarcherCrosses) {
    // One pixel of unit absorption at a time: the stencil's length in it is the marched one.
    for (int n = 0; n < 4; ++n) {
        for (int k = 0; k <= (1 << n); ++k) {
            const auto steps = hrc::traceStencil(n, k);
            double total = 0.0;
            for (const auto& s : steps) total += s.length;
            const double dy = 2 * k - (1 << n), len = std::hypot(1 << n, dy);
            EXPECT_NEAR(total, len, 1e-6) << "level " << n << " ray " << k;
            for (const auto& s : steps) {
                const int w = 24, h = 24, x0 = 4, y0 = 12;
                Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb{}};
                m.absorption.setRgb(x0 + s.du, y0 + s.dv, {1.0f, 1.0f, 1.0f});
                const RayMarcher marcher(m);
                const RaySegment seg =
                    marcher.march({double(x0), y0 + 0.5}, {(1 << n) / len, dy / len}, len, 0.0f);
                EXPECT_NEAR(-std::log(seg.transmittance.r), s.length, 1e-5)
                    << "level " << n << " ray " << k << " cell " << s.du << "," << s.dv;
            }
        }
    }
}

TEST(HrcSweep, MatchesTheLevelByLevelPasses) {
    struct Case {
        const char* name;
        Medium2D medium;
        HrcOptions options;
    };
    std::vector<Case> cases;
    cases.push_back({"random 97x61", randomMedium(97, 61, 7), {}});
    cases.push_back({"random 64x130", randomMedium(64, 130, 8), {}});
    HrcOptions extendFromC0;
    extendFromC0.tracedLevels = 1;
    cases.push_back({"random 80x80 t=1", randomMedium(80, 80, 9), extendFromC0});
    HrcOptions traceFive;
    traceFive.tracedLevels = 5;
    traceFive.crossBlur = false;
    cases.push_back({"random 50x70 t=5", randomMedium(50, 70, 10), traceFive});
    HrcOptions traceSeven;  // beyond the sweep's limit: solved cascade by cascade
    traceSeven.tracedLevels = 7;
    cases.push_back({"random 150x40 t=7", randomMedium(150, 40, 13), traceSeven});
    HrcOptions twoFrustums;
    twoFrustums.frustumMask = 0x5;
    cases.push_back({"pinhole 160x90 +-x", shippedScene("pinhole.json", 160, 90), twoFrustums});
    cases.push_back({"room 128", shippedScene("room.json", 128, 128), {}});
    cases.push_back({"tiny 3x2", randomMedium(3, 2, 11), {}});
    for (const Case& c : cases) {
        const Image expected = levelByLevel(c.medium, c.options);
        for (int threads : {1, 2, 3}) {
            const ThreadLimit limit(threads);
            const Image got = solveHrc(c.medium, c.options).value();
            const double d = maxRelativeDifference(got, expected);
            std::printf("%s, %d threads: max difference %.2e of the largest value\n", c.name,
                        threads, d);
            // Binary16 tables: the exp of one marched run against a product of per-cell exps
            // may round one table entry to the neighbouring half, 2^-11 relative.
            EXPECT_LT(d, 2e-3) << c.name << ", " << threads << " threads";
        }
    }
}

TEST(HrcSweep, ThreadCountDoesNotChangeTheImage) {
    const Medium2D medium = randomMedium(150, 90, 12);
    Image first;
    for (int threads : {1, 2, 4}) {
        const ThreadLimit limit(threads);
        Image got = solveHrc(medium).value();
        if (threads == 1) {
            first = std::move(got);
            continue;
        }
        EXPECT_TRUE(std::equal(got.data(), got.data() + got.size(), first.data()))
            << threads << " threads";
    }
}

TEST(HrcSweep, ReportsEveryPass) {
    const Medium2D medium = shippedScene("room.json", 96, 96);
    std::vector<HrcCpuPass> passes;
    ASSERT_TRUE(solveHrc(medium, {}, &passes));
    ASSERT_EQ(passes.size(), 5u);
    const char* names[] = {"trace", "extend", "merge", "readout", "finish"};
    for (std::size_t i = 0; i < passes.size(); ++i) {
        EXPECT_EQ(passes[i].name, names[i]);
        EXPECT_GE(passes[i].milliseconds, 0.0);
        EXPECT_GT(passes[i].bytes, 0u);
    }
}

}  // namespace
}  // namespace luxel::gi2d
