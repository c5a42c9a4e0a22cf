// Vanilla Radiance Cascades: cascade geometry, analytic answers, the bilinear fix against leaks,
// SDF vs DDA interval tracing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "gi2d/analytic_disk.h"
#include "gi2d/shipped_scenes.h"
#include "luxel/core/metrics.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::gi2d {
namespace {

TEST(RcCascades, RaylibDemoFormulas) {
    RcOptions o;  // spacing 1, 4 rays, base 1
    const auto c = rcCascades(512, 512, o);
    // ceil(log4(724.08 / 1)) + 1 = ceil(4.75) + 1 = 6
    ASSERT_EQ(c.size(), 6u);
    for (std::size_t i = 0; i < c.size(); ++i) {
        const double scale = std::pow(4.0, static_cast<double>(i));
        EXPECT_DOUBLE_EQ(c[i].intervalStart, (scale - 1) / 3);
        EXPECT_DOUBLE_EQ(c[i].intervalEnd - c[i].intervalStart, scale);
        EXPECT_EQ(c[i].rays, 4 * static_cast<int>(scale));
        EXPECT_DOUBLE_EQ(c[i].spacing, std::pow(2.0, static_cast<double>(i)));
        if (i > 0) {
            EXPECT_DOUBLE_EQ(c[i].intervalStart, c[i - 1].intervalEnd);  // contiguous
        }
    }
    EXPECT_EQ(c[0].probesX, 512);
    EXPECT_EQ(c[3].probesX, 64);
    EXPECT_GE(c.back().intervalEnd, std::hypot(512.0, 512.0));  // the top reaches every corner
    o.maxCascades = 3;
    EXPECT_EQ(rcCascades(512, 512, o).size(), 3u);
    o = RcOptions{};
    o.probeSpacing = 2;
    o.baseInterval = 2.0;
    const auto d = rcCascades(300, 200, o);
    EXPECT_EQ(d[0].probesX, 150);
    EXPECT_EQ(d[1].probesY, 50);
    EXPECT_EQ(d.size(), 5u);  // ceil(log4(360.6 / 2)) + 1
}

TEST(RcSolver, DiskInVacuumFollowsTheArcsineLaw) {
    const double R = 48.0, E = 2.0;
    const Medium2D medium =
        rasterize(testing_support::analyticDiskScene(R, static_cast<float>(E))).value();
    for (RcMerge merge : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
        RcOptions o;
        o.merge = merge;
        const Image f = solveRc(medium, o).value();
        for (const auto& probe : testing_support::diskProbes(R, E)) {
            const double got = f.at(probe.x, probe.y, 0);
            std::printf("rc %s disk r/R %.2f: %.5f vs %.5f (%+.2f%%)\n",
                        merge == RcMerge::Vanilla ? "vanilla" : "fix", probe.distanceOverRadius,
                        got, probe.exact, 100 * (got / probe.exact - 1));
            // Vanilla RC rings where an interval ends (docs/algorithms/radiance-cascades-2d.md §5);
            // the fix removes them.
            EXPECT_NEAR(got / probe.exact, 1.0, merge == RcMerge::Vanilla ? 0.07 : 0.015)
                << probe.distanceOverRadius;
        }
    }
}

TEST(RcSolver, BilinearFixReducesLightLeakingThroughAOnePixelWall) {
    Scene2D scene{256, 256, {}, {}, {}, ""};
    scene.shapes.push_back(
        {"light", Circle{{60, 128}, 14}, Material{Rgb(4.0f), Rgb(kOpaqueAbsorption)}});
    scene.shapes.push_back(
        {"wall", Box{{128.5, 128}, {1, 200}, 0.0}, Material{{}, Rgb(kOpaqueAbsorption)}});
    const Medium2D medium = rasterize(scene).value();
    const Image reference = solveReference(medium).value();
    // Light on the far side of the wall, in its shadow.
    auto shadowLight = [&](const Image& f) {
        double sum = 0;
        int n = 0;
        for (int y = 96; y < 160; ++y) {
            for (int x = 136; x < 230; ++x, ++n) sum += f.at(x, y, 0);
        }
        return sum / n;
    };
    RcOptions o;
    o.merge = RcMerge::Vanilla;
    const double vanilla = shadowLight(solveRc(medium, o).value());
    o.merge = RcMerge::BilinearFix;
    const double fixed = shadowLight(solveRc(medium, o).value());
    const double truth = shadowLight(reference);
    std::printf("light behind the wall: reference %.5f, vanilla %.5f, bilinear fix %.5f\n", truth,
                vanilla, fixed);
    EXPECT_GT(vanilla - truth, 2 * std::abs(fixed - truth));
}

TEST(RcSolver, SdfAndDdaTracingAgree) {
    auto scene = loadScene2D(std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/penumbra.json");
    ASSERT_TRUE(scene.ok());
    const Medium2D medium = rasterize(*scene, {256, 256, 16}).value();
    auto sdf = SdfScene::create(*scene, 256, 256);
    ASSERT_TRUE(sdf.ok()) << sdf.error().message();
    for (RcMerge merge : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
        RcOptions o;
        o.merge = merge;
        const Image a = solveRc(medium, o).value();
        const Image b = solveRc(*sdf, scene->boundaryRadiance, o).value();
        const ImageErrors e = compareImages(b, a).value();
        std::printf("sdf vs dda: relative L1 %.4f\n", e.relativeL1);
        // They differ only where the medium has anti-aliased (partly transparent) edge pixels.
        EXPECT_LT(e.relativeL1, 0.03);
    }
    // A scene with a medium cannot be sphere traced.
    auto fog = loadScene2D(std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/fog.json");
    ASSERT_TRUE(fog.ok());
    EXPECT_FALSE(SdfScene::create(*fog, 64, 64).ok());
}

TEST(RcSolver, DebugCascadeAndBadOptions) {
    const Medium2D medium = testing_support::shippedScene("penumbra.json", 64, 64);
    RcOptions o;
    o.debugCascade = 2;
    const Image c2 = solveRc(medium, o).value();
    EXPECT_FALSE(c2 == solveRc(medium).value());
    o.debugCascade = 30;
    EXPECT_FALSE(solveRc(medium, o).ok());
    RcOptions bad;
    bad.baseRays = 0;
    EXPECT_FALSE(solveRc(medium, bad).ok());
    bad = RcOptions{};
    bad.baseInterval = -1;
    EXPECT_FALSE(solveRc(medium, bad).ok());
    // Coarser cascade-0 probes (interpolated to pixels) still give a sensible image.
    const Medium2D larger = testing_support::shippedScene("penumbra.json", 128, 128);
    RcOptions coarse;
    coarse.probeSpacing = 2;
    const Image reference = solveReference(larger).value();
    const double fine = compareImages(solveRc(larger).value(), reference)->relativeL1;
    const double rough = compareImages(solveRc(larger, coarse).value(), reference)->relativeL1;
    std::printf("penumbra 128: relative L1 spacing 1 %.4f, spacing 2 %.4f\n", fine, rough);
    EXPECT_LT(fine, rough);
    EXPECT_LT(rough, 0.17);
}

}  // namespace
}  // namespace luxel::gi2d
