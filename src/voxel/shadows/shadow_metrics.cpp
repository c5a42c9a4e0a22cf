// Visibility error metrics (shadow_metrics.h).
#include "luxel/voxel/shadows/shadow_metrics.h"

#include <algorithm>
#include <cmath>

#include "luxel/core/check.h"

namespace luxel::voxel {
namespace {

bool counts(std::span<const std::uint8_t> mask, std::size_t i) {
    return mask.empty() || mask[i] != 0;
}

}  // namespace

ShadowErrors compareVisibility(std::span<const float> estimate, std::span<const float> truth,
                               std::span<const std::uint8_t> mask) {
    LUXEL_CHECK(estimate.size() == truth.size());
    LUXEL_CHECK(mask.empty() || mask.size() == truth.size());
    ShadowErrors e;
    std::vector<float> errors;
    double sum = 0, sumSq = 0, penumbra = 0, signedPenumbra = 0;
    std::int64_t leaks = 0, falseShadows = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!counts(mask, i)) continue;
        const float v = estimate[i], g = truth[i];
        const double d = std::abs(double(v) - g);
        errors.push_back(static_cast<float>(d));
        sum += d;
        sumSq += d * d;
        if (g > kPenumbraLow && g < kPenumbraHigh) {
            penumbra += d;
            signedPenumbra += double(v) - g;
            ++e.penumbraPixels;
        }
        leaks += g < 0.1f && v > 0.5f;
        falseShadows += g > 0.9f && v < 0.5f;
    }
    e.pixels = static_cast<std::int64_t>(errors.size());
    if (e.pixels == 0) return e;
    const double n = double(e.pixels);
    e.maeAll = sum / n;
    e.rmse = std::sqrt(sumSq / n);
    e.maePenumbra = e.penumbraPixels > 0 ? penumbra / double(e.penumbraPixels) : 0.0;
    e.biasPenumbra = e.penumbraPixels > 0 ? signedPenumbra / double(e.penumbraPixels) : 0.0;
    e.leakRate = double(leaks) / n;
    e.falseShadowRate = double(falseShadows) / n;
    const std::size_t k = std::min(errors.size() - 1, static_cast<std::size_t>(0.99 * n));
    std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(k), errors.end());
    e.p99 = errors[k];
    return e;
}

double seamMetric(std::span<const float> estimate, std::span<const float> truth, int width,
                  int height, std::span<const std::uint8_t> band,
                  std::span<const std::uint8_t> mask) {
    const std::size_t n = static_cast<std::size_t>(width) * height;
    LUXEL_CHECK(estimate.size() == n && truth.size() == n && band.size() == n);
    double sum = 0;
    std::int64_t count = 0;
    for (int y = 0; y + 1 < height; ++y) {
        for (int x = 0; x + 1 < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            const std::size_t r = i + 1, d = i + width;
            if (!band[i] || !counts(mask, i) || !counts(mask, r) || !counts(mask, d)) continue;
            const double ge =
                std::hypot(double(estimate[r]) - estimate[i], double(estimate[d]) - estimate[i]);
            const double gt = std::hypot(double(truth[r]) - truth[i], double(truth[d]) - truth[i]);
            sum += std::abs(ge - gt);
            ++count;
        }
    }
    return count > 0 ? sum / double(count) : 0.0;
}

double temporalFlicker(const std::vector<std::vector<float>>& estimate,
                       const std::vector<std::vector<float>>& truth,
                       const std::vector<std::vector<std::uint8_t>>& masks) {
    LUXEL_CHECK(estimate.size() == truth.size() && masks.size() == truth.size());
    if (estimate.size() < 2) return 0.0;
    double total = 0;
    for (std::size_t t = 1; t < estimate.size(); ++t) {
        double de = 0, dg = 0;
        std::int64_t count = 0;
        for (std::size_t i = 0; i < truth[t].size(); ++i) {
            if (!masks[t][i] || !masks[t - 1][i]) continue;
            de += std::abs(double(estimate[t][i]) - estimate[t - 1][i]);
            dg += std::abs(double(truth[t][i]) - truth[t - 1][i]);
            ++count;
        }
        if (count > 0) total += (de - dg) / double(count);
    }
    return total / double(estimate.size() - 1);
}

}  // namespace luxel::voxel
