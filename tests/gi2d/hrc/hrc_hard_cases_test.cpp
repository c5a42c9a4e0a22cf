// HRC where cascades struggle (docs/algorithms/holographic-radiance-cascades.md §12): light through
// 1 px diagonal slits, the error around a small very bright disk (the whole image, and one
// frustum's share by direction), how light dims with distance in fog, and the image change when
// a light moves by a fraction of a pixel. Each measures HRC against the reference solver and
// prints the values. Slit transmission, fog and the moving light hold the goals (10%, 2%, 0.1%);
// the star bound is the measured value with headroom, far above the 2% goal (§12.2 says why).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "gi2d/medium_from_json.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::gi2d {
namespace {

using testing_support::mediumFrom;

double luminance(const Image& image, int x, int y) {
    const Rgb c = image.rgb(x, y);
    return (c.r + c.g + c.b) / 3.0;
}

// The shipped slit maze: mean fluence right of the first wall's far face, HRC over the reference.
TEST(HrcHardCases, SlitMazeTransmissionPastTheFirstWall) {
    auto scene = loadScene2D(std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/hard/slit-maze.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const Medium2D medium = rasterize(*scene, {256, 256, 16}).value();
    ReferenceOptions ref;
    ref.rays = 256;
    const Image truth = solveReference(medium, ref).value();
    const Image hrc = solveHrc(medium).value();
    // First wall: centre line x = 68 + (y - 128) / tan(60 deg), 3 px thick; count from 3 px past
    // its far face to 3 px before the second wall's near face (x = 134 - (y - 128) / tan(68 deg)).
    double sumTruth = 0, sumHrc = 0;
    for (int y = 0; y < 256; ++y) {
        const double cy = y + 0.5 - 128;
        const double first = 68 + cy / std::tan(60 * M_PI / 180) + 1.5 / std::sin(60 * M_PI / 180);
        const double second = 134 + cy / std::tan(112 * M_PI / 180);
        for (int x = 0; x < 256; ++x) {
            const double cx = x + 0.5;
            if (cx < first + 3 || cx > second - 4) continue;
            if (medium.emission.rgb(x, y).r > 0) continue;
            sumTruth += luminance(truth, x, y);
            sumHrc += luminance(hrc, x, y);
        }
    }
    ASSERT_GT(sumTruth, 0);
    const double ratio = sumHrc / sumTruth;
    std::printf("slit maze: HRC / reference past the first wall = %.3f\n", ratio);
    EXPECT_NEAR(ratio, 1.0, 0.10);
}

// A disk of radius 1.6 px, 200 times brighter than the sky, in an empty 96 x 96 canvas: the RMSE
// over the annulus 4-40 px from its centre, relative to the annulus mean (a 4-/8-fold star is
// most of it).
TEST(HrcHardCases, NoStarAroundASmallBrightDisk) {
    const std::string json = R"({"canvas": [96, 96], "boundary_radiance": [0.01, 0.01, 0.01],
        "shapes": [{"type": "circle", "center": [48.4, 45.7], "radius": 1.6,
                    "emission": [1, 1, 1], "intensity": 200, "opaque": true}]})";
    const Medium2D medium = mediumFrom(json, 96);
    ReferenceOptions ref;
    ref.rays = 2048;
    const Image truth = solveReference(medium, ref).value();
    auto annulusRmse = [&](const Image& hrc) {
        double sq = 0, sum = 0;
        int count = 0;
        for (int y = 0; y < 96; ++y) {
            for (int x = 0; x < 96; ++x) {
                const double r = std::hypot(x + 0.5 - 48.4, y + 0.5 - 45.7);
                if (r < 4 || r > 40) continue;
                const double d = luminance(hrc, x, y) - luminance(truth, x, y);
                sq += d * d;
                sum += luminance(truth, x, y);
                ++count;
            }
        }
        return std::sqrt(sq / count) / (sum / count);
    };
    HrcOptions cascadesAlone;
    cascadesAlone.exactDirectLight = false;
    const double cascades = annulusRmse(solveHrc(medium, cascadesAlone).value());
    const double rmseOfMean = annulusRmse(solveHrc(medium).value());
    std::printf(
        "bright disk: RMSE over the annulus %.2f%% of its mean (%.2f%% by the cascades alone)\n",
        100 * rmseOfMean, 100 * cascades);
    // The cascades alone: measured 4.24% (12.4% with the reads of Eq 14-17 alone, 7.65% with
    // two-row reads at cascades 0 and 1 only, 4.68% before cascade 0's depth scale; §5.1 and §3.1
    // of docs/algorithms/holographic-radiance-cascades.md); the rest of the star is §12.2's. The
    // bound catches it getting worse.
    EXPECT_LT(cascades, 0.055);
    // With the disk's direct light exact (§12.5) the star is gone: measured 1.74%, the goal 2%.
    EXPECT_LT(rmseOfMean, 0.02);
}

// The +x frustum alone, without the cross blur, against the reference restricted to its quarter
// of the directions (within 45 degrees of +x, from each pixel centre), around the same disk
// without sky: in 16 bins of the direction from a pixel to the disk (5.6 degrees each), 8-40 px
// out, every bin gets its share within 4.5%. With the reads of §5.1 at cascades 0 and 1 only, the
// bins between the directions of cascade 2's rays were 6% too dark (§12.2).
TEST(HrcHardCases, OneFrustumGetsItsShareInEveryDirection) {
    const Medium2D medium = mediumFrom(R"({"canvas": [96, 96],
        "shapes": [{"type": "circle", "center": [48.4, 45.7], "radius": 1.6,
                    "emission": [1, 1, 1], "intensity": 200, "opaque": true}]})",
                                       96);
    constexpr int kRays = 2048;
    const RayMarcher marcher(medium);
    Image quarter(96, 96, 3);
    parallelForRange(96, 1, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            for (int x = 0; x < 96; ++x) {
                Rgb sum{0, 0, 0};
                for (int k = 0; k < kRays; ++k) {
                    const double a =
                        (k + 0.5) / kRays * (std::numbers::pi / 2) - std::numbers::pi / 4;
                    sum = sum +
                          marcher.march({x + 0.5, y + 0.5}, {std::cos(a), std::sin(a)}).radiance;
                }
                // Mean radiance over all directions (the fluence convention): the quarter's
                // integral over 2 pi.
                quarter.setRgb(x, y, sum * static_cast<float>(0.25 / kRays));
            }
        }
    });
    HrcOptions options;
    options.frustumMask = 1;
    options.crossBlur = false;
    const Image hrc = solveHrc(medium, options).value();
    constexpr int kBins = 16;
    double binHrc[kBins] = {}, binTruth[kBins] = {};
    for (int y = 0; y < 96; ++y) {
        for (int x = 0; x < 96; ++x) {
            const double dx = 48.4 - (x + 0.5), dy = 45.7 - (y + 0.5);
            const double r = std::hypot(dx, dy),
                         degrees = std::atan2(dy, dx) * 180 / std::numbers::pi;
            if (r < 8 || r > 40 || std::abs(degrees) >= 45) continue;
            const int bin = static_cast<int>((degrees + 45) / 90 * kBins);
            binHrc[bin] += luminance(hrc, x, y);
            binTruth[bin] += luminance(quarter, x, y);
        }
    }
    double worst = 0;
    std::printf("+x frustum / its quarter of the truth, by direction to the disk:");
    for (int b = 0; b < kBins; ++b) {
        const double ratio = binHrc[b] / binTruth[b];
        std::printf(" %.3f", ratio);
        worst = std::max(worst, std::abs(ratio - 1));
    }
    std::printf("\n");
    EXPECT_LT(worst, 0.045);
}

// A lamp in uniform fog of optical depth 0.08 per pixel (dense-fog.json's), 64 x 64: HRC over the
// reference, summed over the pixels 8 px or more from the lamp's pixels. Cascade 0's two rays run
// along the frustum's edges, and every path the read-out gathers starts with one of them: counted
// with the diagonal's full length they added about 0.3 px of fog to every path, and the far field
// was 3-4% too dark (§3.1 and §12.3 of docs/algorithms/holographic-radiance-cascades.md).
TEST(HrcHardCases, FogDimsWithDistanceAsInTheReference) {
    const Medium2D medium = mediumFrom(R"({"canvas": [64, 64], "background": {"absorption": 0.08},
        "shapes": [{"type": "circle", "center": [30.3, 33.6], "radius": 6,
                    "emission": [1, 1, 1], "intensity": 6, "opaque": true}]})",
                                       64);
    ReferenceOptions ref;
    ref.rays = 2048;
    const Image truth = solveReference(medium, ref).value();
    const Image hrc = solveHrc(medium).value();
    double sumHrc = 0, sumTruth = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            double nearest = 1e9;
            for (int ey = 0; ey < 64; ++ey) {
                for (int ex = 0; ex < 64; ++ex) {
                    if (medium.emission.rgb(ex, ey).r > 0)
                        nearest = std::min(nearest, std::hypot(ex - x, ey - y));
                }
            }
            if (nearest < 8) continue;
            sumHrc += luminance(hrc, x, y);
            sumTruth += luminance(truth, x, y);
        }
    }
    ASSERT_GT(sumTruth, 0);
    const double ratio = sumHrc / sumTruth;
    std::printf("fog 8 px and more from the lamp: HRC / reference = %.4f\n", ratio);
    // Measured 0.9679 with the diagonal's full length and §5.1's former cascade-0 weights, 0.9903
    // now.
    EXPECT_NEAR(ratio, 1.0, 0.02);
}

// A static lamp lights a room; a small second light behind a wall moves by 0.5 and 1 px. Where
// the reference changes by less than 0.1%, the HRC image should not change either.
TEST(HrcHardCases, MovingALightBySubpixelStepsChangesNothingElsewhere) {
    auto scene = [](double x) {
        return R"({"canvas": [96, 96], "shapes": [
            {"type": "circle", "center": [20, 20], "radius": 4, "emission": [1, 1, 1],
             "intensity": 4, "opaque": true},
            {"type": "box", "center": [60, 48], "size": [3, 70], "opaque": true},
            {"type": "circle", "center": [)" +
               std::to_string(x) + R"(, 48.3], "radius": 1.2, "emission": [1, 0.8, 0.6],
             "intensity": 30, "opaque": true}]})";
    };
    ReferenceOptions ref;
    ref.rays = 1024;
    const Medium2D at0 = mediumFrom(scene(75.2), 96);
    const Image truth0 = solveReference(at0, ref).value();
    const Image hrc0 = solveHrc(at0).value();
    for (double step : {0.5, 1.0}) {
        const Medium2D moved = mediumFrom(scene(75.2 + step), 96);
        const Image truth1 = solveReference(moved, ref).value();
        const Image hrc1 = solveHrc(moved).value();
        double changeHrc = 0, base = 0;
        int count = 0;
        for (int y = 0; y < 96; ++y) {
            for (int x = 0; x < 96; ++x) {
                const double t0 = luminance(truth0, x, y), t1 = luminance(truth1, x, y);
                if (!(t0 > 0) || std::abs(t1 - t0) >= 1e-3 * t0) continue;
                changeHrc += std::abs(luminance(hrc1, x, y) - luminance(hrc0, x, y));
                base += luminance(hrc0, x, y);
                ++count;
            }
        }
        ASSERT_GT(count, 96 * 96 / 4) << "the unchanged region should be a large part of the room";
        const double change = changeHrc / base;
        std::printf(
            "light moved %.1f px: HRC changes %.3f%% where the reference changes < 0.1%% "
            "(%d px)\n",
            step, 100 * change, count);
        EXPECT_LT(change, 1e-3);
    }
}

}  // namespace
}  // namespace luxel::gi2d
