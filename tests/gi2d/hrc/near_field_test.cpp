// HRC's exact near field in fog (docs/algorithms/holographic-radiance-cascades.md §12.3, "An
// exact near field in fog"): it brings a lamp in dense fog near the reference, acts only where
// every pixel absorbs enough to bound the rays, and leaves every other canvas as it was, bit for
// bit.
#include "gi2d/hrc/near_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>

#include "gi2d/medium_from_json.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::gi2d::hrc {
namespace {

using testing_support::mediumFrom;

// Two lamps in fog, dense-fog.json's optical depth per pixel unless `fog` says otherwise.
std::string lampsInFog(double fog) {
    return R"({"canvas": [80, 80], "background": {"absorption": )" + std::to_string(fog) +
           R"(}, "shapes": [
        {"type": "circle", "center": [30.3, 33.6], "radius": 6, "emission": [1, 0.7, 0.4],
         "intensity": 6, "opaque": true},
        {"type": "circle", "center": [58.6, 55.2], "radius": 3.5, "emission": [0.4, 0.7, 1],
         "intensity": 8, "opaque": true}]})";
}

// RMSE of `image` against `truth`, as a fraction of the truth's mean.
double relativeRmse(const Image& image, const Image& truth) {
    double squared = 0, sum = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const double d = image.data()[i] - truth.data()[i];
        squared += d * d;
        sum += truth.data()[i];
    }
    const double n = static_cast<double>(truth.size());
    return std::sqrt(squared / n) / (sum / n);
}

bool sameBits(const Image& a, const Image& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(HrcNearField, BringsLampsInDenseFogNearTheReference) {
    const Medium2D medium = mediumFrom(lampsInFog(0.08), 80);
    ASSERT_FALSE(planNearField(medium).empty());
    ReferenceOptions ref;
    ref.rays = 2048;
    const Image truth = solveReference(medium, ref).value();
    // The near field alone: the smaller lamp is compact, and §12.5's direct light would take it.
    HrcOptions on;
    on.exactDirectLight = false;
    HrcOptions off = on;
    off.exactNearField = false;
    const double before = relativeRmse(solveHrc(medium, off).value(), truth);
    const double after = relativeRmse(solveHrc(medium, on).value(), truth);
    std::printf(
        "lamps in fog, RMSE of the mean against 2048 directions: %.2f%% without the "
        "near field, %.2f%% with it\n",
        before * 100, after * 100);
    // Measured 4.81% and 0.82%.
    EXPECT_GT(before, 0.035);
    EXPECT_LT(after, 0.02);
}

TEST(HrcNearField, LeavesCanvasesWithoutAnAbsorptionBoundBitIdentical) {
    // Vacuum around the lamps, and fog too thin to stop a ray within the longest reach.
    for (double fog : {0.0, 0.004, 0.01}) {
        const Medium2D medium = mediumFrom(lampsInFog(fog), 80);
        EXPECT_TRUE(planNearField(medium).empty()) << fog;
        HrcOptions off;
        off.exactNearField = false;
        EXPECT_TRUE(sameBits(solveHrc(medium).value(), solveHrc(medium, off).value())) << fog;
    }
}

TEST(HrcNearField, ActsWhereEveryPixelBoundsTheRays) {
    // ln(1000) / 0.06 = 115 px: within the longest reach, 512 px; 0.01 (691 px) is not (above).
    const Medium2D fog = mediumFrom(lampsInFog(0.06), 80);
    const NearFieldPlan plan = planNearField(fog);
    ASSERT_FALSE(plan.empty());
    EXPECT_NEAR(plan.reach, std::log(1000.0) / 0.06, 0.01);
    // The pixels are those within kNearFieldRadius of a lamp's pixel, the lamps' own included.
    const int w = fog.width();
    for (std::uint32_t p : plan.pixels) {
        const int x = static_cast<int>(p % w), y = static_cast<int>(p / w);
        const double toLamp = std::min(std::hypot(x + 0.5 - 30.3, y + 0.5 - 33.6) - 6,
                                       std::hypot(x + 0.5 - 58.6, y + 0.5 - 55.2) - 3.5);
        EXPECT_LT(toLamp, kNearFieldRadius + 0.75) << x << " " << y;
    }
    // ... about the area of the two disks grown by the radius, give or take a pixel.
    const double pi = std::numbers::pi, k = kNearFieldRadius;
    EXPECT_GT(plan.pixels.size(), pi * ((6 + k - 1) * (6 + k - 1) + (3.5 + k - 1) * (3.5 + k - 1)));
    EXPECT_LT(plan.pixels.size(), pi * ((6 + k + 1) * (6 + k + 1) + (3.5 + k + 1) * (3.5 + k + 1)));
    // One pixel of vacuum anywhere lets a ray run on: no gather.
    Medium2D hole = fog;
    hole.absorption.setRgb(77, 2, {0.06f, 0.0f, 0.06f});
    EXPECT_TRUE(planNearField(hole).empty());
    // Nor without a light.
    Medium2D dark = fog;
    std::fill_n(dark.emission.data(), dark.emission.size(), 0.0f);
    EXPECT_TRUE(planNearField(dark).empty());
    // Nor where the lights are so many that the rays would cost more than the budget.
    Medium2D glowing = fog;
    std::fill_n(glowing.emission.data(), glowing.emission.size(), 1.0f);
    EXPECT_TRUE(planNearField(glowing).empty());
    // The option and fewer frustums turn it off.
    HrcOptions off;
    off.exactNearField = false;
    const Image with = solveHrc(fog).value(), without = solveHrc(fog, off).value();
    EXPECT_FALSE(sameBits(with, without));
    // Outside the plan's pixels nothing changes.
    std::vector<std::uint8_t> inPlan(static_cast<std::size_t>(w) * fog.height(), 0);
    for (std::uint32_t p : plan.pixels) inPlan[p] = 1;
    for (int y = 0; y < fog.height(); ++y) {
        for (int x = 0; x < w; ++x) {
            if (inPlan[static_cast<std::size_t>(y) * w + x]) continue;
            ASSERT_EQ(with.rgb(x, y).r, without.rgb(x, y).r) << x << " " << y;
        }
    }
}

// In uniform emitting fog the mean radiance is known: E (1 - exp(-sigma d)) averaged over the
// directions, d the way to the canvas's edge; far from the edge (exp(-sigma d) < the cutoff) it
// is E within the cutoff.
TEST(HrcNearField, GathersTheExactMeanRadiance) {
    const int size = 96;
    const float sigma = 0.2f, e = 2.0f;
    Medium2D medium{Image(size, size, 3), Image(size, size, 3), Rgb{}};
    std::fill_n(medium.absorption.data(), medium.absorption.size(), sigma);
    std::fill_n(medium.emission.data(), medium.emission.size(), e);
    const RayMarcher marcher(medium);
    const Rgb centre = nearFieldGatherAt(marcher, size / 2, size / 2);
    EXPECT_NEAR(centre.g, e, e * kNearFieldCutoff * 1.5);
    // From the corner pixel three quarters of the directions leave within a pixel or so.
    const Rgb corner = nearFieldGatherAt(marcher, 0, 0);
    EXPECT_LT(corner.g, 0.8f * e);
    EXPECT_GT(corner.g, 0.2f * e);
}

}  // namespace
}  // namespace luxel::gi2d::hrc
