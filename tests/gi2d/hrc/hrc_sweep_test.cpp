// The streaming HRC solver (docs/algorithms/holographic-radiance-cascades.md §7.1) against the
// level-by-level passes it reorders: the same intervals, cones and read-out, so the same image up
// to float rounding, at any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/finish.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/level_by_level.h"
#include "gi2d/hrc/ray_tables.h"
#include "gi2d/hrc/readout.h"
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

// Mostly vacuum: light crosses the whole frame, so the top cascade's far plane shows in the image
// (behind randomMedium's opaque blocks it is all but black).
Medium2D clearMedium(int w, int h, std::uint64_t seed) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb{0.3f, 0.2f, 0.1f}};
    Pcg32 rng(seed);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float kind = rng.nextFloat();
            if (kind < 0.03f) {
                m.absorption.setRgb(x, y, {2.0f, 1.0f, 3.0f});
                m.emission.setRgb(x, y, {5.0f * rng.nextFloat(), 2.0f, 0.5f});
            } else if (kind < 0.1f) {
                m.absorption.setRgb(x, y, {0.02f, 0.05f, 0.01f});
            }
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
    cases.push_back({"clear 150x70", clearMedium(150, 70, 14), {}});
    cases.push_back({"clear 40x130", clearMedium(40, 130, 15), {}});
    for (Case& c : cases) {
        c.options.exactDirectLight = false;  // the cascades alone (§12.5 adds to both alike)
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

TEST(HrcSweep, PlaneZeroNeverReachesTheImage) {
    // The sweep never computes plane 0 of any cascade (§7.1): pixel x reads plane x + 1 out, a
    // merge of plane p >= 1 reads the upper planes (p + 1) / 2, p / 2 and p / 2 + 1 and an extend
    // the planes 2p and 2p + 1 below, all >= 1. Through the level-by-level passes, which do
    // compute it: NaN in plane 0 of every table and cone leaves the read-out bit for bit.
    const Medium2D medium = clearMedium(70, 50, 16);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int r = 0; r < 4; ++r) {
        const hrc::FrustumFrame frame = hrc::makeFrame(static_cast<hrc::Frustum>(r), 70, 50);
        const int levels = hrc::cascadeCount(frame.length);
        auto readOut = [&](bool poison) {
            hrc::RayTables tables;
            tables.reset(frame.length, frame.rows, levels);
            hrc::traceBaseLevels(tables, RayMarcher(hrc::frameMedium(medium, frame)), 3);
            hrc::extendLevels(tables, 3);
            hrc::Interval bad;
            bad.radiance = {nan, nan, nan};
            bad.transmittance = {nan, nan, nan};
            for (int n = 0; n < levels && poison; ++n) {
                for (int k = 0; k <= (1 << n); ++k) {
                    for (int y = 0; y < frame.rows; ++y) tables.set(n, 0, y, k, bad);
                }
            }
            hrc::ConeBuffer buffers[2];
            const hrc::ConeBuffer* upper = nullptr;
            for (int n = levels - 1, current = 0; n >= 0; --n, current ^= 1) {
                hrc::mergeCascade(tables, n, upper, medium.boundaryRadiance, buffers[current]);
                for (int i = 0; i < (1 << n) && poison; ++i) {
                    for (int y = 0; y < frame.rows; ++y)
                        buffers[current].set(0, i, y, {nan, nan, nan});
                }
                upper = &buffers[current];
            }
            Image beyond(70, 50, 3);
            hrc::readOut(frame, *upper, 0, medium.boundaryRadiance, beyond);
            return beyond;
        };
        const Image clean = readOut(false), poisoned = readOut(true);
        EXPECT_EQ(std::memcmp(clean.data(), poisoned.data(), clean.size() * sizeof(float)), 0)
            << "frustum " << r;
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
