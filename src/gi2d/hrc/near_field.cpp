// The exact near field of §12.3: eligibility by the least absorption, the pixels near the lights,
// and the gather itself (the GPU twin is hrc_near_field.comp.glsl).
#include "gi2d/hrc/near_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "gi2d/hrc/light_scores.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {

NearFieldPlan planNearField(const Medium2D& medium) {
    return planNearField(LightScores::of(medium));
}

NearFieldPlan planNearField(const LightScores& scores) {
    NearFieldPlan plan;
    const int w = scores.width(), h = scores.height();
    const std::size_t pixels = static_cast<std::size_t>(w) * h;
    if (pixels == 0) return plan;
    // The least sigma over every pixel and channel bounds every ray; NaN or 0 bound nothing (the
    // rows' scans found it: a canvas in vacuum plans nothing more).
    const float least = scores.leastAbsorption();
    if (!(least > 0.0f)) return plan;
    const float reach = std::log(1.0f / kNearFieldCutoff) / least;
    if (!(reach <= kNearFieldMaxReach)) return plan;

    // Lights as NearLightMask tells them, then every pixel within kNearFieldRadius of one.
    const float brightest = scores.brightest();
    if (!(brightest > 0.0f)) return plan;
    const float threshold = lightScoreThreshold(brightest);
    // The rays' cost against the canvas's: beyond the budget the gather is off altogether. The
    // lights are among the gathered pixels, so too many of them end it before the stamping.
    const double stepsPerPixel = kNearFieldRays * std::min<double>(reach, std::hypot(w, h));
    const double budget = kNearFieldStepsPerPixel *
                          std::max(static_cast<double>(pixels), kNearFieldBudgetFloorPixels);
    std::size_t lights = 0;
    for (int y = 0; y < h; ++y) {
        if (!(scores.rowBrightest(y) >= threshold)) continue;
        const float* row = scores.row(y);
        for (int x = 0; x < w; ++x) lights += row[x] >= threshold ? 1 : 0;
    }
    if (static_cast<double>(lights) * stepsPerPixel > budget) return plan;
    constexpr int r = kNearFieldRadius;
    std::vector<std::uint8_t> near(pixels, 0);
    for (int y = 0; y < h; ++y) {
        if (!(scores.rowBrightest(y) >= threshold)) continue;
        const float* row = scores.row(y);
        for (int x = 0; x < w; ++x) {
            if (!(row[x] >= threshold)) continue;
            for (int dy = std::max(-r, -y); dy <= std::min(r, h - 1 - y); ++dy) {
                for (int dx = std::max(-r, -x); dx <= std::min(r, w - 1 - x); ++dx) {
                    if (dx * dx + dy * dy <= r * r)
                        near[static_cast<std::size_t>(y + dy) * w + x + dx] = 1;
                }
            }
        }
    }
    for (std::size_t i = 0; i < pixels; ++i) {
        if (near[i]) plan.pixels.push_back(static_cast<std::uint32_t>(i));
    }
    if (static_cast<double>(plan.pixels.size()) * stepsPerPixel > budget) plan.pixels.clear();
    plan.reach = reach;
    return plan;
}

namespace {

// The directions 2 pi (k + 1/2) / N, the same for every pixel: made once.
const std::array<Vec2d, kNearFieldRays>& gatherDirections() {
    static const std::array<Vec2d, kNearFieldRays> directions = [] {
        std::array<Vec2d, kNearFieldRays> d;
        const double step = 2.0 * std::numbers::pi / kNearFieldRays;
        for (int k = 0; k < kNearFieldRays; ++k) {
            const double angle = (k + 0.5) * step;
            d[static_cast<std::size_t>(k)] = {std::cos(angle), std::sin(angle)};
        }
        return d;
    }();
    return directions;
}

}  // namespace

Rgb nearFieldGatherAt(const RayMarcher& marcher, int x, int y, double reach) {
    const Vec2d origin{x + 0.5, y + 0.5};
    double sum[3] = {0, 0, 0};
    for (const Vec2d& direction : gatherDirections()) {
        const RaySegment ray = marcher.march(origin, direction, reach, kNearFieldCutoff);
        for (int c = 0; c < 3; ++c) sum[c] += ray.radiance[c];
    }
    const double norm = 1.0 / kNearFieldRays;
    return {static_cast<float>(sum[0] * norm), static_cast<float>(sum[1] * norm),
            static_cast<float>(sum[2] * norm)};
}

void gatherNearFieldInPlace(const Medium2D& medium, const NearFieldPlan& plan, Image& fluence) {
    if (plan.empty()) return;
    const RayMarcher marcher(medium);
    const int w = medium.width();
    parallelForRange(static_cast<int>(plan.pixels.size()), 16, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const int x = static_cast<int>(plan.pixels[static_cast<std::size_t>(i)] % w);
            const int y = static_cast<int>(plan.pixels[static_cast<std::size_t>(i)] / w);
            fluence.setRgb(x, y, nearFieldGatherAt(marcher, x, y, plan.reach));
        }
    });
}

}  // namespace luxel::gi2d::hrc
