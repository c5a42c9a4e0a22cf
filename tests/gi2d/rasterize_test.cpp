// Rasterisation: coverage-as-opacity compositing (docs/algorithms/pixel-medium.md §1), draw order,
// scaling, sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "luxel/core/check.h"

#include "luxel/gi2d/rasterize.h"

namespace luxel::gi2d {
namespace {

Shape circle(Vec2d c, double r, Rgb e, Rgb a) {
    return {"c", Circle{c, r}, Material{e, a}};
}
Shape box(Vec2d min, Vec2d max, Rgb e, Rgb a) {
    return {"b", Box{(min + max) * 0.5, max - min, 0.0}, Material{e, a}};
}

// The coverage rule of §1 alone, without the emitter power factor of §4 (emitter_power_test.cpp).
RasterOptions coverageRuleOnly(int width = 0, int height = 0) {
    RasterOptions o;
    o.width = width;
    o.height = height;
    o.conserveEmitterPower = false;
    return o;
}

TEST(Rasterize, OpaqueEmitterEdgesKeepFullRadiance) {
    // Half-covered pixels of an opaque emitter: E stays E_s and sigma = -ln(1 - c) (medium2d §1),
    // never the naive c * E_s.
    Scene2D scene{16, 8, {}, {}, {}, ""};
    scene.shapes.push_back(box({0, 0}, {8.5, 8}, Rgb(2.0f), Rgb(kOpaqueAbsorption)));
    const Medium2D m = rasterize(scene, coverageRuleOnly()).value();
    EXPECT_FLOAT_EQ(m.emission.at(8, 3, 0), 2.0f);                // half covered
    EXPECT_NEAR(m.absorption.at(8, 3, 0), std::log(2.0), 1e-4);   // T = 1 - 0.5
    EXPECT_FLOAT_EQ(m.emission.at(3, 3, 1), 2.0f);                // inside
    EXPECT_NEAR(m.absorption.at(3, 3, 1), kMaxAbsorption, 1e-3);  // opaque, clamped
    EXPECT_EQ(m.emission.at(9, 3, 0), 0.0f);                      // outside
    EXPECT_EQ(m.absorption.at(9, 3, 0), 0.0f);
}

TEST(Rasterize, PartialCoverageOfAbsorberAveragesTransmittance) {
    const float sigma = 0.7f;
    Scene2D scene{8, 8, {}, {}, {}, ""};
    scene.shapes.push_back(box({0, 0}, {4.25, 8}, Rgb(0.0f), Rgb(sigma)));
    const Medium2D m = rasterize(scene).value();
    const double T = 1.0 - 0.25 * (1.0 - std::exp(-sigma));
    EXPECT_NEAR(m.absorption.at(4, 2, 2), -std::log(T), 1e-5);
    EXPECT_NEAR(m.absorption.at(1, 2, 2), sigma, 1e-6);
}

TEST(Rasterize, LaterShapesOverwriteEarlierOnes) {
    Scene2D scene{32, 32, {}, {}, {}, ""};
    scene.shapes.push_back(box({0, 0}, {32, 32}, Rgb(1.0f, 0.0f, 0.0f), Rgb(1.0f)));
    scene.shapes.push_back(box({8, 8}, {24, 24}, Rgb(0.0f, 3.0f, 0.0f), Rgb(2.0f)));
    scene.shapes.push_back(circle({16, 16}, 4, Rgb(0.0f), Rgb(0.0f)));  // a clear hole
    const Medium2D m = rasterize(scene, coverageRuleOnly()).value();
    EXPECT_EQ(m.emission.rgb(2, 2), Rgb(1.0f, 0.0f, 0.0f));
    EXPECT_NEAR(m.emission.at(10, 10, 1), 3.0f, 1e-5);
    EXPECT_NEAR(m.absorption.at(10, 10, 0), 2.0f, 1e-5);
    EXPECT_EQ(m.absorption.rgb(16, 16), Rgb(0.0f));
    EXPECT_EQ(m.emission.rgb(16, 16), Rgb(0.0f));
}

TEST(Rasterize, BackgroundFillsTheCanvas) {
    Scene2D scene{5, 3, {Rgb(0.5f), Rgb(0.01f)}, {}, {}, ""};
    const Medium2D m = rasterize(scene).value();
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            EXPECT_NEAR(m.absorption.at(x, y, 0), 0.01f, 1e-6);
            EXPECT_NEAR(m.emission.at(x, y, 2), 0.5f, 1e-5);
        }
    }
}

TEST(Rasterize, CircleCoverageMatchesItsArea) {
    // Sum of coverage (opacity of a fully opaque shape = coverage) equals pi r^2.
    Scene2D scene{64, 48, {}, {}, {}, ""};
    const double r = 13.3;
    scene.shapes.push_back(circle({31.7, 22.2}, r, Rgb(1.0f), Rgb(kOpaqueAbsorption)));
    const Medium2D m = rasterize(scene).value();
    double area = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) area += 1.0 - std::exp(-m.absorption.at(x, y, 0));
    }
    EXPECT_NEAR(area, M_PI * r * r, 0.5);
}

TEST(Rasterize, RotatedBoxAndPolygonCoverTheSameSquare) {
    // A square rotated by 45 degrees as a Box and as a Polygon: identical coverage.
    Scene2D a{40, 40, {}, {}, {}, ""}, b = a;
    a.shapes.push_back({"box", Box{{20, 20}, {16, 16}, 45.0}, Material{Rgb(1.0f), Rgb(2.0f)}});
    const double h = 8.0 * std::sqrt(2.0);
    b.shapes.push_back({"poly", Polygon{{{20, 20 - h}, {20 + h, 20}, {20, 20 + h}, {20 - h, 20}}},
                        Material{Rgb(1.0f), Rgb(2.0f)}});
    const Medium2D ma = rasterize(a).value(), mb = rasterize(b).value();
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) {
            EXPECT_NEAR(ma.absorption.at(x, y, 0), mb.absorption.at(x, y, 0), 2e-3)
                << x << "," << y;
        }
    }
}

TEST(Rasterize, MovingShapeChangesTheMediumSmoothly) {
    // Anti-aliasing: a sub-pixel move changes the total coverage by about the swept area.
    double previous = -1;
    for (int step = 0; step <= 8; ++step) {
        Scene2D scene{32, 32, {}, {}, {}, ""};
        scene.shapes.push_back(circle({10.0 + step * 0.125, 16}, 5, Rgb(1.0f), Rgb(0.5f)));
        const Medium2D m = rasterize(scene).value();
        double sumX = 0, sum = 0;
        for (int y = 0; y < 32; ++y) {
            for (int x = 0; x < 32; ++x) {
                const double c = 1.0 - std::exp(-m.absorption.at(x, y, 0));
                sum += c;
                sumX += c * (x + 0.5);
            }
        }
        const double centroid = sumX / sum;
        EXPECT_NEAR(centroid, 10.0 + step * 0.125, 0.02);
        if (previous >= 0) {
            EXPECT_NEAR(centroid - previous, 0.125, 0.02);
        }
        previous = centroid;
    }
}

TEST(Rasterize, ScalingKeepsOpticalDepthAndOpacity) {
    Scene2D scene{40, 30, {Rgb(0.0f), Rgb(0.02f)}, {}, {}, ""};
    scene.shapes.push_back(box({10, 10}, {20, 20}, Rgb(1.0f), Rgb(kOpaqueAbsorption)));
    const Medium2D m = rasterize(scene, coverageRuleOnly(80, 60)).value();
    EXPECT_EQ(m.width(), 80);
    EXPECT_EQ(m.height(), 60);
    EXPECT_NEAR(m.absorption.at(1, 1, 0), 0.01f, 1e-6);             // sigma per pixel halves at 2x
    EXPECT_NEAR(m.absorption.at(30, 30, 0), kMaxAbsorption, 1e-3);  // opaque stays opaque
    EXPECT_NEAR(m.emission.at(30, 30, 0), 1.0f, 1e-6);
}

TEST(Rasterize, NonSquareNonPowerOfTwoCanvas) {
    Scene2D scene{37, 19, {}, {}, {}, ""};
    scene.shapes.push_back(circle({36, 18}, 3, Rgb(1.0f), Rgb(kOpaqueAbsorption)));
    const Medium2D m = rasterize(scene, coverageRuleOnly()).value();
    EXPECT_EQ(m.width(), 37);
    EXPECT_EQ(m.height(), 19);
    EXPECT_NEAR(m.emission.at(36, 18, 0), 1.0f, 1e-6);
}

TEST(Rasterize, RejectsAbsurdSizes) {
    Scene2D scene{64, 64, {}, {}, {}, ""};
    for (auto [w, h] : {std::pair{-5, 10}, {10, 100000}, {70000, 70000}}) {
        auto r = rasterize(scene, {w, h, 16});
        ASSERT_FALSE(r.ok()) << w << "x" << h;
        EXPECT_NE(r.error().message().find("is invalid"), std::string::npos) << r.error().message();
    }
    // Fits the side limit but not the memory of any machine this runs on: refused, not crashed.
    auto huge = rasterize(scene, {65536, 65536, 16});
    if (!huge.ok()) {
        EXPECT_NE(huge.error().message().find("only"), std::string::npos) << huge.error().message();
    }
}

}  // namespace
}  // namespace luxel::gi2d

namespace luxel::gi2d {
namespace {

TEST(RasterizeImageLayer, EmissionSpriteAndAbsorptionMap) {
    // A 2x1 emission image: left texel lit (opaque emitter), right texel dark (leaves the
    // background); stretched over an 8x4 canvas region.
    auto emission = std::make_shared<Image>(2, 1, 3);
    emission->setRgb(0, 0, Rgb(0.5f, 1.0f, 0.25f));
    Scene2D scene{8, 4, {Rgb(0.0f), Rgb(0.1f)}, {}, {}, ""};
    ImageLayer layer;
    layer.size = {8, 4};
    layer.emission = emission;
    scene.shapes.push_back({"sprite", layer, Material{{}, {}, 2.0f}});
    Medium2D m = rasterize(scene).value();
    EXPECT_NEAR(m.emission.at(1, 1, 1), 2.0f, 1e-5);  // intensity 2 x 1.0
    EXPECT_NEAR(m.absorption.at(1, 1, 0), kMaxAbsorption, 1e-3);
    EXPECT_NEAR(m.absorption.at(6, 1, 0), 0.1f, 1e-6);  // background kept
    EXPECT_EQ(m.emission.at(6, 1, 0), 0.0f);

    // An absorption map alone: sigma = value * scale over the whole rectangle.
    auto absorption = std::make_shared<Image>(1, 1, 1);
    absorption->at(0, 0, 0) = 0.5f;
    ImageLayer mask;
    mask.position = {4, 0};
    mask.size = {4, 4};
    mask.absorption = absorption;
    mask.absorptionScale = 0.6f;
    scene.shapes = {{"mask", mask, Material{}}};
    m = rasterize(scene).value();
    EXPECT_NEAR(m.absorption.at(5, 2, 2), 0.3f, 1e-5);
    EXPECT_NEAR(m.absorption.at(2, 2, 2), 0.1f, 1e-6);
}

TEST(CheckMacros, FailedCheckPrintsBothOperandsAndAborts) {
    const int a = 3, b = 4;
    EXPECT_DEATH(LUXEL_CHECK_EQ(a + 1, b + 1), "a \\+ 1 == b \\+ 1 with a = 4, b = 5");
    EXPECT_DEATH(LUXEL_CHECK(a > b), "Check failed: a > b");
}

}  // namespace
}  // namespace luxel::gi2d
