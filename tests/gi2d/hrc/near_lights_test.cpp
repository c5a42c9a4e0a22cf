// The near-light mask of docs/algorithms/holographic-radiance-cascades.md §12.3.
#include "gi2d/hrc/near_lights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "luxel/core/rng.h"

namespace luxel::gi2d::hrc {
namespace {

Medium2D darkMedium(int w, int h) {
    return Medium2D{Image(w, h, 3), Image(w, h, 3), Rgb{}};
}

void light(Medium2D& m, int x, int y, float e, float sigma) {
    m.emission.setRgb(x, y, {e, e, e});
    m.absorption.setRgb(x, y, {sigma, sigma, sigma});
}

// The kept fraction in 64ths by brute force over every light: none within 1 px of a light's
// centre, the whole from 3 px, linear in the distance between.
int expectedKept(const std::vector<std::pair<int, int>>& lights, int x, int y) {
    double nearest = 1e9;
    for (const auto& [lx, ly] : lights) nearest = std::min(nearest, std::hypot(x - lx, y - ly));
    return static_cast<int>(std::lround(64.0 * std::clamp((nearest - 1.0) / 2.0, 0.0, 1.0)));
}

TEST(NearLightMask, KeepsTheBlendByDistanceToTheNearestLight) {
    Medium2D m = darkMedium(23, 17);
    light(m, 10, 8, 8.0f, 2.0f);     // score 8
    light(m, 2, 2, 0.2f, 1.0f);      // score 0.2 >= 8 / 64: a light
    light(m, 20, 14, 0.1f, 1.0f);    // score 0.1 < 8 / 64: not one
    light(m, 3, 14, 50.0f, 0.001f);  // score 0.05: bright, but nearly transparent
    const NearLightMask mask = NearLightMask::fromMedium(m);
    EXPECT_EQ(mask.at(10, 8), 0);
    EXPECT_EQ(mask.at(11, 8), 0);
    EXPECT_EQ(mask.at(11, 9), 13);
    EXPECT_EQ(mask.at(12, 8), 32);
    EXPECT_EQ(mask.at(12, 9), 40);
    EXPECT_EQ(mask.at(12, 10), 59);
    EXPECT_EQ(mask.at(13, 8), 64);
    EXPECT_EQ(mask.at(1, 1), 13);
    EXPECT_EQ(mask.at(0, 0), 59);
    EXPECT_EQ(mask.at(20, 14), 64);
    EXPECT_EQ(mask.at(3, 14), 64);
    // Columns and rows with a pixel closer than 3 px to a light.
    EXPECT_TRUE(mask.columnNear(12));
    EXPECT_FALSE(mask.columnNear(13));
    EXPECT_TRUE(mask.rowNear(10));
    EXPECT_FALSE(mask.rowNear(11));
    EXPECT_FALSE(mask.rowNear(5));
    EXPECT_EQ(mask.bytes().size() % 4, 0u);
    EXPECT_EQ(mask.bytes().size(), NearLightMask::bytesFor(23, 17));
}

TEST(NearLightMask, MatchesBruteForceOnScatteredLights) {
    for (const auto& [w, h] : {std::pair{64, 48}, std::pair{5, 70}, std::pair{130, 3}}) {
        Medium2D m = darkMedium(w, h);
        std::vector<std::pair<int, int>> lights;
        Pcg32 rng(static_cast<std::uint64_t>(w * 1000 + h));
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                if (rng.nextFloat() < 0.02f) {
                    light(m, x, y, 1.0f + rng.nextFloat(), 1.0f);
                    lights.emplace_back(x, y);
                }
            }
        }
        const NearLightMask mask = NearLightMask::fromMedium(m);
        int wrong = 0;
        std::vector<bool> column(static_cast<std::size_t>(w)), row(static_cast<std::size_t>(h));
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const int kept = expectedKept(lights, x, y);
                wrong += mask.at(x, y) != kept;
                if (kept < 64)
                    column[static_cast<std::size_t>(x)] = row[static_cast<std::size_t>(y)] = true;
            }
        }
        EXPECT_EQ(wrong, 0) << w << "x" << h;
        for (int x = 0; x < w; ++x)
            EXPECT_EQ(mask.columnNear(x), column[static_cast<std::size_t>(x)]) << x;
        for (int y = 0; y < h; ++y)
            EXPECT_EQ(mask.rowNear(y), row[static_cast<std::size_t>(y)]) << y;
    }
}

TEST(NearLightMask, NoEmissionKeepsTheWholeBlend) {
    const NearLightMask mask = NearLightMask::fromMedium(darkMedium(9, 7));
    for (int y = 0; y < 7; ++y) {
        for (int x = 0; x < 9; ++x) EXPECT_EQ(mask.at(x, y), 64);
    }
}

}  // namespace
}  // namespace luxel::gi2d::hrc
