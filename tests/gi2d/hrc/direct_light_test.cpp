// Exact direct light from compact lights (docs/algorithms/holographic-radiance-cascades.md §12.5):
// the split reproduces the reference solver, the direct part alone matches the reference for one
// light behind an occluder, which lights qualify, and the gain on sub-pixel lights.
#include "gi2d/hrc/direct_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <utility>

#include "gi2d/hrc/compact_lights.h"
#include "gi2d/medium_from_json.h"
#include "luxel/core/memory.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d::hrc {
namespace {

using testing_support::mediumFrom;

struct Errors {
    double relativeL1, rmseOfMean;
};

Errors errors(const Image& image, const Image& truth) {
    double squared = 0, absolute = 0, sum = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const double d = image.data()[i] - truth.data()[i];
        squared += d * d;
        absolute += std::abs(d);
        sum += truth.data()[i];
    }
    const double n = static_cast<double>(truth.size());
    return {absolute / sum, std::sqrt(squared / n) / (sum / n)};
}

// The largest value of `a` and the largest |a - b|, to bound two fluences' difference relatively.
std::pair<double, double> largestAndDifference(const Image& a, const Image& b) {
    double most = 0, differs = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        most = std::max(most, static_cast<double>(a.data()[i]));
        differs = std::max(differs, std::abs(static_cast<double>(a.data()[i] - b.data()[i])));
    }
    return {most, differs};
}

bool sameBits(const Image& a, const Image& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

Image referenceOf(const Medium2D& medium, int rays = 2048) {
    ReferenceOptions ref;
    ref.rays = rays;
    return solveReference(medium, ref).value();
}

// A light of radius 1.2 px, an opaque box casting a shadow, a dim sky.
const char* kLightAndOccluder = R"({"canvas": [96, 96], "boundary_radiance": [0.02, 0.02, 0.02],
    "shapes": [{"type": "circle", "center": [30.3, 41.6], "radius": 1.2,
                "emission": [1, 0.8, 0.6], "intensity": 40, "opaque": true},
               {"type": "box", "center": [55, 50], "size": [6, 18], "angle": 20,
                "opaque": true}]})";

TEST(HrcDirectLight, DirectPartMatchesTheReferenceForOneLightBehindAnOccluder) {
    Medium2D medium = mediumFrom(kLightAndOccluder, 96);
    medium.boundaryRadiance = {};  // the light's own fluence alone
    const DirectLight direct = exactDirectLight(medium);
    ASSERT_FALSE(direct.empty());
    const Errors e = errors(direct.fluence, referenceOf(medium));
    std::printf("one light's direct part against 2048 directions: rel. L1 %.2f%%, RMSE %.2f%%\n",
                100 * e.relativeL1, 100 * e.rmseOfMean);
    EXPECT_LT(e.relativeL1, 0.01);
    EXPECT_LT(e.rmseOfMean, 0.02);
}

TEST(HrcDirectLight, SplitReproducesTheUnsplitReference) {
    // The reference of the medium without the compact light, plus its direct part, against the
    // reference of the whole medium (the same directions: linearity in the emission).
    const std::string json = R"({"canvas": [80, 80], "boundary_radiance": [0.05, 0.05, 0.05],
        "shapes": [{"type": "circle", "center": [24.6, 30.2], "radius": 0.8,
                    "emission": [1, 1, 1], "intensity": 30, "opaque": true},
                   {"type": "box", "center": [60, 40], "size": [4, 50], "emission": [0.5, 0.6, 1],
                    "intensity": 2, "opaque": true},
                   {"type": "circle", "center": [40, 52], "radius": 5, "opaque": true}]})";
    const Medium2D medium = mediumFrom(json, 80);
    const DirectLight direct = exactDirectLight(medium);
    ASSERT_FALSE(direct.empty());
    ASSERT_EQ(findCompactLights(medium).size(), 1u);  // the long wall light is not compact
    Image split = referenceOf(withoutDirectLights(medium, direct));
    addDirectLight(direct, split);
    const Errors e = errors(split, referenceOf(medium));
    std::printf("split against unsplit reference: rel. L1 %.2f%%, RMSE %.2f%%\n",
                100 * e.relativeL1, 100 * e.rmseOfMean);
    EXPECT_LT(e.relativeL1, 0.01);
    EXPECT_LT(e.rmseOfMean, 0.02);
}

TEST(HrcDirectLight, LargeLightsAndTheOptionLeaveTheSolveBitIdentical) {
    // A light of radius 8 px is no compact light: the solve is the cascades' alone, to the bit.
    const Medium2D large = mediumFrom(R"({"canvas": [64, 64], "shapes": [{"type": "circle",
        "center": [30, 30], "radius": 8, "emission": [1, 1, 1], "opaque": true}]})",
                                      64);
    EXPECT_TRUE(findCompactLights(large).empty());
    HrcOptions off;
    off.exactDirectLight = false;
    EXPECT_TRUE(sameBits(solveHrc(large).value(), solveHrc(large, off).value()));
    // A small one is split, and the option turns that off.
    const Medium2D small = mediumFrom(kLightAndOccluder, 96);
    EXPECT_EQ(findCompactLights(small).size(), 1u);
    EXPECT_FALSE(sameBits(solveHrc(small).value(), solveHrc(small, off).value()));
    // A debug view (one frustum) never splits.
    HrcOptions one;
    one.frustumMask = 1;
    HrcOptions oneOff = one;
    oneOff.exactDirectLight = false;
    EXPECT_TRUE(sameBits(solveHrc(small, one).value(), solveHrc(small, oneOff).value()));
}

TEST(HrcDirectLight, ShareFallsWithTheLightsSize) {
    // RMS radius below kCompactFullRadius: all of it; a disk of radius 4 (RMS about 2.9): part.
    auto shareOf = [](double radius) {
        const Medium2D m =
            mediumFrom(R"({"canvas": [48, 48], "shapes": [{"type": "circle",
            "center": [24.3, 23.8], "radius": )" +
                           std::to_string(radius) + R"(, "emission": [1, 1, 1], "opaque": true}]})",
                       48);
        const auto lights = findCompactLights(m);
        return lights.empty() ? 0.0 : lights[0].share;
    };
    EXPECT_EQ(shareOf(0.35), 1.0);
    EXPECT_EQ(shareOf(3.2), 1.0);
    const double part = shareOf(4.0);
    EXPECT_GT(part, 0.0);
    EXPECT_LT(part, 1.0);
    EXPECT_EQ(shareOf(5.5), 0.0);
}

TEST(HrcDirectLight, StaysWithinTheBudget) {
    // Forty lights of radius 0.35 px between opaque walls (like scenes/2d/hard/subpixel-lights.json
    // at 128 px): every one is taken and the marched pixels stay within the budget.
    std::string shapes;
    for (int i = 0; i < 40; ++i) {
        if (!shapes.empty()) shapes += ",";
        shapes += R"({"type": "circle", "center": [)" + std::to_string(6.3 + (i % 8) * 15.2) +
                  ", " + std::to_string(10.7 + (i / 8) * 23.1) +
                  R"(], "radius": 0.35, "emission": [1, 0.9, 0.7], "intensity": 20,
                      "opaque": true})";
    }
    for (int wall = 0; wall < 4; ++wall) {
        shapes += R"(, {"type": "box", "center": [)" + std::to_string(13 + wall * 30) +
                  R"(, 64], "size": [2, 90], "opaque": true})";
    }
    const Medium2D medium =
        mediumFrom(R"({"canvas": [128, 128], "shapes": [)" + shapes + "]}", 128);
    const DirectLight direct = exactDirectLight(medium);
    ASSERT_FALSE(direct.empty());
    const double budget = kDirectWorkPerPixel * kDirectBudgetFloorPixels;
    std::printf("forty lights: work %.1f per canvas pixel of 256 x 256\n",
                static_cast<double>(direct.work) / kDirectBudgetFloorPixels);
    EXPECT_LE(static_cast<double>(direct.work), budget);
    std::size_t lightPixels = 0;
    for (const CompactLight& light : findCompactLights(medium)) lightPixels += light.pixels.size();
    EXPECT_EQ(direct.removed.size(), lightPixels);  // every light taken
}

TEST(HrcDirectLight, SubpixelLightsBetweenWallsNearTheReference) {
    // Six lights of radius 0.35 px 1.5-4 px from opaque walls, a dim sky: the cascades alone
    // miss by several percent (their cones carry the lights, §12.3); with the direct light exact
    // the rest is the sky's and the walls'.
    const std::string json = R"({"canvas": [96, 96], "boundary_radiance": [0.02, 0.02, 0.03],
        "shapes": [
          {"type": "box", "center": [30, 48], "size": [3, 70], "opaque": true},
          {"type": "box", "center": [64, 48], "size": [3, 70], "opaque": true},
          {"type": "circle", "center": [33.4, 22.3], "radius": 0.35, "emission": [1, 0.9, 0.7],
           "intensity": 30, "opaque": true},
          {"type": "circle", "center": [27.1, 60.6], "radius": 0.35, "emission": [0.7, 0.9, 1],
           "intensity": 30, "opaque": true},
          {"type": "circle", "center": [47.7, 40.2], "radius": 0.35, "emission": [1, 1, 1],
           "intensity": 30, "opaque": true},
          {"type": "circle", "center": [60.2, 71.5], "radius": 0.35, "emission": [1, 0.6, 0.4],
           "intensity": 30, "opaque": true},
          {"type": "circle", "center": [68.6, 30.9], "radius": 0.35, "emission": [0.6, 1, 0.6],
           "intensity": 30, "opaque": true},
          {"type": "circle", "center": [12.2, 80.4], "radius": 0.35, "emission": [1, 1, 0.8],
           "intensity": 30, "opaque": true}]})";
    const Medium2D medium = mediumFrom(json, 96);
    const Image truth = referenceOf(medium, 4096);
    HrcOptions off;
    off.exactDirectLight = false;
    const Errors before = errors(solveHrc(medium, off).value(), truth);
    const Errors after = errors(solveHrc(medium).value(), truth);
    std::printf(
        "six sub-pixel lights: rel. L1 / RMSE of the mean %.2f%% / %.2f%% by the cascades, "
        "%.2f%% / %.2f%% with the direct light\n",
        100 * before.relativeL1, 100 * before.rmseOfMean, 100 * after.relativeL1,
        100 * after.rmseOfMean);
    EXPECT_LT(after.relativeL1, 0.02);
    EXPECT_LT(after.rmseOfMean, 0.04);
    EXPECT_LT(after.rmseOfMean, 0.6 * before.rmseOfMean);
}

TEST(HrcDirectLight, VacuumSectorsMatchTheDenseFan) {
    // Random compact lights among random occluders (kept off the light) and a patch of thin fog:
    // fans whose vacuum sectors are not split give the dense fans' light to rounding, for much
    // less work.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto number = [&](double lo, double hi) { return std::to_string(lo + (hi - lo) * u(rng)); };
    std::uint64_t denseWork = 0, sparseWork = 0;
    for (int scene = 0; scene < 6; ++scene) {
        const double lx = 20 + 40 * u(rng), ly = 20 + 40 * u(rng);
        std::string shapes = R"({"type": "circle", "center": [)" + std::to_string(lx) + ", " +
                             std::to_string(ly) + R"(], "radius": )" + number(0.3, 2.5) +
                             R"(, "emission": [1, 0.8, 0.6], "intensity": 30, "opaque": true})";
        for (int k = 0; k < 5;) {
            const double bx = 80 * u(rng), by = 80 * u(rng);
            if (std::hypot(bx - lx, by - ly) < 10) continue;
            ++k;
            const std::string sx = number(1, 9), sy = number(1, 9), angle = number(0, 90);
            shapes += R"(, {"type": "box", "center": [)" + std::to_string(bx) + ", " +
                      std::to_string(by) + R"(], "size": [)" + sx + ", " + sy + R"(], "angle": )" +
                      angle + R"(, "opaque": true})";
        }
        if (scene % 2 == 1) {
            const std::string fx = number(0, 80), fy = number(0, 80);
            shapes += R"(, {"type": "circle", "center": [)" + fx + ", " + fy +
                      R"(], "radius": 9, "absorption": 0.05})";
        }
        const Medium2D medium =
            mediumFrom(R"({"canvas": [80, 80], "shapes": [)" + shapes + "]}", 80);
        DirectLightOptions dense;
        dense.vacuumSectors = false;
        const DirectLight a = exactDirectLight(medium, dense);
        const DirectLight b = exactDirectLight(medium);
        ASSERT_FALSE(a.empty()) << "scene " << scene;
        ASSERT_EQ(a.removed, b.removed);
        const auto [most, differs] = largestAndDifference(a.fluence, b.fluence);
        EXPECT_LE(differs, 1e-6 * most) << "scene " << scene;
        denseWork += a.work, sparseWork += b.work;
    }
    std::printf("vacuum sectors, random scenes: work %.2f of the dense fans'\n",
                static_cast<double>(sparseWork) / static_cast<double>(denseWork));
    EXPECT_LT(sparseWork, denseWork);
    // One light and one occluder in vacuum: most sectors are vacuum (the work also counts the
    // near gather and the pixels gathered, which do not change: 0.77 when written).
    const Medium2D open = mediumFrom(kLightAndOccluder, 96);
    DirectLightOptions dense;
    dense.vacuumSectors = false;
    const double ratio = static_cast<double>(exactDirectLight(open).work) /
                         static_cast<double>(exactDirectLight(open, dense).work);
    std::printf("vacuum sectors, one light and an occluder: work %.2f of the dense fans'\n", ratio);
    EXPECT_LT(ratio, 0.85);
}

TEST(HrcDirectLight, GreyFogMarchesAsEachChannel) {
    // The fans share one exp over the three channels where the absorption is grey: the light
    // through grey fog matches the same fog with its blue a float's step denser (each channel's
    // own exp), to 10^-5 of its maximum; and the fans in the fog stop short of the canvas edge.
    Medium2D grey = mediumFrom(kLightAndOccluder, 96);
    Medium2D tinted = grey;
    for (int y = 0; y < 96; ++y) {
        for (int x = 0; x < 96; ++x) {
            const Rgb s = grey.absorption.rgb(x, y);
            if (s.r > 0) continue;  // the light and the occluder stay
            grey.absorption.setRgb(x, y, {0.2f, 0.2f, 0.2f});
            tinted.absorption.setRgb(x, y, {0.2f, 0.2f, std::nextafter(0.2f, 1.0f)});
        }
    }
    const DirectLight a = exactDirectLight(grey), b = exactDirectLight(tinted);
    ASSERT_FALSE(a.empty());
    ASSERT_EQ(a.removed, b.removed);
    const auto [most, differs] = largestAndDifference(a.fluence, b.fluence);
    EXPECT_GT(most, 0.0);
    EXPECT_LE(differs, 1e-5 * most);
    // 0.2 per px: the fans fade (T < 1e-4) within 47 px; the far corner, 84 px off, gets nothing.
    EXPECT_EQ(a.fluence.at(95, 95, 0), 0.0f);
}

}  // namespace
// The split's memory is checked before any of it is allocated: 10^10 pixels' reduced medium,
// direct fluence and search buffers (some 400 GB) are refused with the size named.
TEST(HrcDirectLight, RefusesASplitThatDoesNotFit) {
    if (availableMemoryBytes() == 0) GTEST_SKIP() << "this machine does not say what is available";
    EXPECT_TRUE(checkDirectLightMemory(256, 256).ok());
    const Status huge = checkDirectLightMemory(100000, 100000);
    ASSERT_FALSE(huge.ok());
    EXPECT_NE(huge.error().message().find("HRC's direct light at 100000x100000 needs"),
              std::string::npos)
        << huge.error().message();
}

}  // namespace luxel::gi2d::hrc
