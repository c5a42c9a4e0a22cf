// Errors of a visibility image against its ground truth (docs/algorithms/voxel-shadows.md,
// validation): whole-image and penumbra-masked MAE, RMSE, the 99th percentile error, light leaks,
// false shadows, seams in the blend band and temporal flicker.
//
// Images are width x height visibilities in [0, 1], rows top to bottom; `mask` (same size, or
// empty for all pixels) selects the pixels that count (e.g. those that see a surface).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace luxel::voxel {

struct ShadowErrors {
    double maeAll = 0;        // mean |V - V_gt|
    double maePenumbra = 0;   // the same over 0.02 < V_gt < 0.98
    double biasPenumbra = 0;  // mean V - V_gt there: > 0 too light, < 0 too dark
    double rmse = 0;
    double p99 = 0;              // 99th percentile of |V - V_gt|
    double leakRate = 0;         // fraction with V_gt < 0.1 and V > 0.5
    double falseShadowRate = 0;  // fraction with V_gt > 0.9 and V < 0.5
    std::int64_t pixels = 0, penumbraPixels = 0;
};

inline constexpr float kPenumbraLow = 0.02f, kPenumbraHigh = 0.98f;

ShadowErrors compareVisibility(std::span<const float> estimate, std::span<const float> truth,
                               std::span<const std::uint8_t> mask = {});

// Seams: mean over the pixels in `band` of | |grad V| - |grad V_gt| | (forward differences, both
// neighbours in the mask): a blend that switches methods inside the band shows up as gradient the
// ground truth does not have.
double seamMetric(std::span<const float> estimate, std::span<const float> truth, int width,
                  int height, std::span<const std::uint8_t> band,
                  std::span<const std::uint8_t> mask = {});

// Temporal flicker over a sequence of frames: mean over frames t >= 1 of
// mean |V_t - V_{t-1}| - mean |V_gt,t - V_gt,t-1| (the truth's own change removed), over the
// pixels masked in both frames. 0 for fewer than two frames.
double temporalFlicker(const std::vector<std::vector<float>>& estimate,
                       const std::vector<std::vector<float>>& truth,
                       const std::vector<std::vector<std::uint8_t>>& masks);

}  // namespace luxel::voxel
