// The light scores of docs/algorithms/holographic-radiance-cascades.md §12.3, made once a solve
// and read by the compact lights' search, the near-light mask and the near field's plan.
#include "gi2d/hrc/light_scores.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "gi2d/hrc/direct_light.h"
#include "gi2d/medium_from_json.h"
#include "luxel/core/rng.h"

namespace luxel::gi2d::hrc {
namespace {

// Emission and absorption drawn from [0, 4) and [0, 2) (both sides of min(sigma, 1)), on a width
// that leaves a tail after the vectors.
Medium2D randomMedium(int w, int h, std::uint64_t seed) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb{}};
    Pcg32 rng(seed);
    for (std::size_t i = 0; i < m.emission.size(); ++i) {
        m.emission.data()[i] = 4.0f * rng.nextFloat();
        m.absorption.data()[i] = 0.001f + 2.0f * rng.nextFloat();
    }
    return m;
}

float scoreOf(const Medium2D& m, int x, int y) {
    const Rgb e = m.emission.rgb(x, y), s = m.absorption.rgb(x, y);
    return std::max(e.r * std::min(s.r, 1.0f),
                    std::max(e.g * std::min(s.g, 1.0f), e.b * std::min(s.b, 1.0f)));
}

TEST(HrcLightScores, CanvasMatchesThePixelFormula) {
    const Medium2D m = randomMedium(37, 11, 5);
    const LightScores scores = LightScores::of(m);
    ASSERT_EQ(scores.width(), 37);
    ASSERT_EQ(scores.height(), 11);
    float brightest = 0, least = std::numeric_limits<float>::infinity();
    for (int y = 0; y < 11; ++y) {
        float rowMost = 0;
        for (int x = 0; x < 37; ++x) {
            EXPECT_EQ(scores.row(y)[x], scoreOf(m, x, y)) << x << ", " << y;
            rowMost = std::max(rowMost, scoreOf(m, x, y));
            const Rgb s = m.absorption.rgb(x, y);
            least = std::min({least, s.r, s.g, s.b});
        }
        EXPECT_EQ(scores.rowBrightest(y), rowMost) << y;
        brightest = std::max(brightest, rowMost);
    }
    EXPECT_EQ(scores.brightest(), brightest);
    EXPECT_EQ(scores.leastAbsorption(), least);
}

TEST(HrcLightScores, LeastAbsorptionIsZeroWhereSomePixelDoesNotAbsorb) {
    // In a vector's lanes and in the row's tail alike; NaN counts as not absorbing.
    for (const int x : {3, 36}) {
        for (const float sigma : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()}) {
            Medium2D m = randomMedium(37, 5, 9);
            m.absorption.at(x, 2, 1) = sigma;
            EXPECT_EQ(LightScores::of(m).leastAbsorption(), 0.0f) << x << " " << sigma;
        }
    }
    EXPECT_GT(LightScores::of(randomMedium(37, 5, 9)).leastAbsorption(), 0.0f);
}

TEST(HrcLightScores, RescoredRowsMatchAFreshScan) {
    Medium2D m = randomMedium(41, 23, 7);
    LightScores scores = LightScores::of(m);
    // The brightest pixel dimmed: the canvas's brightest falls with it.
    const float before = scores.brightest();
    for (int y = 9; y < 13; ++y) {
        for (int x = 0; x < 41; ++x) {
            for (int c = 0; c < 3; ++c) m.emission.at(x, y, c) *= 0.25f;
        }
    }
    m.emission.setRgb(5, 10, {100.0f, 0.0f, 0.0f});
    scores.rescoreRows(m, 9, 13);
    const LightScores fresh = LightScores::of(m);
    for (int y = 0; y < 23; ++y) {
        EXPECT_EQ(std::memcmp(scores.row(y), fresh.row(y), 41 * sizeof(float)), 0) << y;
        EXPECT_EQ(scores.rowBrightest(y), fresh.rowBrightest(y)) << y;
    }
    EXPECT_EQ(scores.brightest(), fresh.brightest());
    EXPECT_NE(scores.brightest(), before);
}

TEST(HrcLightScores, SplitHandsTheRestItsOwnScores) {
    // Two compact lights and a long wall light (no compact one): the rest's medium has the
    // compact lights' emission scaled down, and the scores the split hands on are that medium's.
    const Medium2D medium = testing_support::mediumFrom(
        R"({"canvas": [64, 64], "shapes": [
            {"type": "circle", "center": [20.3, 30.6], "radius": 1.2, "emission": [1, 0.8, 0.6],
             "intensity": 40, "opaque": true},
            {"type": "circle", "center": [44.5, 12.2], "radius": 0.6, "emission": [1, 1, 1],
             "intensity": 30, "opaque": true},
            {"type": "box", "center": [32, 58], "size": [60, 3], "emission": [1, 1, 1],
             "intensity": 1, "opaque": true}]})",
        64);
    LightScores scores = LightScores::of(medium);
    bool solvedRest = false;
    const auto solved = solveSplittingDirectLight(
        medium, scores, HrcOptions{},
        [&](const Medium2D& rest, LightScores& restScores, const HrcOptions&) -> Result<Image> {
            solvedRest = true;
            const LightScores fresh = LightScores::of(rest);
            EXPECT_NE(fresh.brightest(), LightScores::of(medium).brightest());
            EXPECT_EQ(restScores.brightest(), fresh.brightest());
            for (int y = 0; y < 64; ++y) {
                EXPECT_EQ(std::memcmp(restScores.row(y), fresh.row(y), 64 * sizeof(float)), 0) << y;
            }
            return Image(64, 64, 3);
        },
        [](const DirectLightSplit&) {});
    ASSERT_TRUE(solved.has_value());
    EXPECT_TRUE(solvedRest);
}

}  // namespace
}  // namespace luxel::gi2d::hrc
