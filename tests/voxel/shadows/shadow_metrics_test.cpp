// Shadow metrics on synthetic images with known answers.
#include "luxel/voxel/shadows/shadow_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace luxel::voxel {
namespace {

TEST(ShadowMetrics, CountsErrorsLeaksAndFalseShadows) {
    const std::vector<float> truth = {0.0f, 0.5f, 1.0f, 1.0f, 0.05f, 0.3f};
    const std::vector<float> est = {0.9f, 0.4f, 1.0f, 0.2f, 0.05f, 0.3f};
    const ShadowErrors e = compareVisibility(est, truth);
    EXPECT_EQ(e.pixels, 6);
    EXPECT_EQ(e.penumbraPixels, 3);  // 0.5, 0.05, 0.3
    EXPECT_NEAR(e.maeAll, (0.9 + 0.1 + 0.8) / 6.0, 1e-6);
    EXPECT_NEAR(e.maePenumbra, 0.1 / 3.0, 1e-6);
    EXPECT_NEAR(e.rmse, std::sqrt((0.81 + 0.01 + 0.64) / 6.0), 1e-6);
    EXPECT_NEAR(e.leakRate, 1.0 / 6.0, 1e-9);
    EXPECT_NEAR(e.falseShadowRate, 1.0 / 6.0, 1e-9);
    EXPECT_NEAR(e.p99, 0.9, 1e-6);
    const std::vector<std::uint8_t> mask = {0, 1, 1, 0, 1, 1};
    const ShadowErrors m = compareVisibility(est, truth, mask);
    EXPECT_EQ(m.pixels, 4);
    EXPECT_EQ(m.leakRate, 0.0);
    EXPECT_NEAR(m.maeAll, 0.1 / 4.0, 1e-6);
}

TEST(ShadowMetrics, SeamSeesAStepTheTruthDoesNotHave) {
    const int w = 8, h = 4;
    std::vector<float> truth(w * h), est(w * h);
    std::vector<std::uint8_t> band(w * h, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            truth[y * w + x] = x / 8.0f;                         // a smooth ramp
            est[y * w + x] = x / 8.0f + (x >= 4 ? 0.2f : 0.0f);  // the same with a seam
        }
    EXPECT_NEAR(seamMetric(truth, truth, w, h, band), 0.0, 1e-9);
    // One column of 7 in each of the 3 counted rows jumps by 0.2.
    EXPECT_NEAR(seamMetric(est, truth, w, h, band), 0.2 / 7.0, 1e-6);
    std::fill(band.begin(), band.end(), 0);
    EXPECT_EQ(seamMetric(est, truth, w, h, band), 0.0);
}

TEST(ShadowMetrics, FlickerRemovesTheTruthsOwnChange) {
    const std::vector<std::vector<float>> truth = {{0.0f, 1.0f}, {0.5f, 1.0f}, {0.5f, 1.0f}};
    const std::vector<std::vector<float>> still = truth;
    const std::vector<std::vector<float>> noisy = {{0.0f, 1.0f}, {0.5f, 0.8f}, {0.5f, 1.0f}};
    const std::vector<std::vector<std::uint8_t>> masks(3, {1, 1});
    EXPECT_NEAR(temporalFlicker(still, truth, masks), 0.0, 1e-9);
    // Frame 1: estimate changes 0.5 + 0.2, truth 0.5; frame 2: 0.2 vs 0: mean (0.1 + 0.1) / 2.
    EXPECT_NEAR(temporalFlicker(noisy, truth, masks), 0.1, 1e-6);
}

}  // namespace
}  // namespace luxel::voxel
