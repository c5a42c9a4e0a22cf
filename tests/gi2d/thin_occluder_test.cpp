// Opaque shapes at least 1 px thick block all light at any position and angle
// (docs/algorithms/pixel-medium.md §5), and slits in thick walls stay as open as before.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {
namespace {

constexpr double kPi = std::numbers::pi;

Shape opaqueWall(Geometry g) {
    return Shape{"wall", std::move(g), Material{Rgb(0.0f), Rgb(kOpaqueAbsorption)}};
}

// Largest transmittance of rays that cross a capsule wall of `thickness` through its middle part,
// at crossing angles up to 80 degrees from its normal.
double worstTransmittance(double thickness, double angleDegrees, double offset) {
    const double a = angleDegrees * kPi / 180;
    const Vec2d u{std::cos(a), std::sin(a)}, n{-u.y, u.x};
    const Vec2d centre = Vec2d{32.0, 32.0} + n * offset;
    Scene2D scene{64, 64, {}, {}, {}, ""};
    scene.shapes.push_back(opaqueWall(Capsule{centre - u * 26.0, centre + u * 26.0, thickness}));
    const RayMarcher marcher(rasterize(scene).value());
    double worst = 0;
    for (double along = -12; along <= 12; along += 0.0625) {
        for (double cross = -80; cross <= 80; cross += 5) {
            const double c = cross * kPi / 180;
            const Vec2d dir = n * std::cos(c) + u * std::sin(c);
            const Vec2d p = centre + u * along;
            worst = std::max<double>(worst,
                                     marcher.segment(p - dir * 6.0, p + dir * 6.0).transmittance.r);
        }
    }
    return worst;
}

TEST(ThinOccluders, WallsAtLeastOnePixelThickBlockAllLightAtAnyPositionAndAngle) {
    double worst = 0;
    for (double thickness : {1.0, 1.5, 2.0, 3.0}) {
        for (double angle = 0; angle <= 90; angle += 5) {
            for (double offset = 0; offset < 1; offset += 0.125) {
                const double t = worstTransmittance(thickness, angle, offset);
                worst = std::max(worst, t);
                EXPECT_LT(t, 1e-3)
                    << "thickness " << thickness << " angle " << angle << " offset " << offset;
            }
        }
    }
    std::printf("largest transmittance across walls 1-3 px thick: %.3g\n", worst);
}

// Vertical rays through a 1 px slit in a 3 px wall: the open width that gets through,
// integral of T over x. Exact: 1 px.
double slitOpenWidth(double slitLeft) {
    Scene2D scene{32, 16, {}, {}, {}, ""};
    scene.shapes.push_back(opaqueWall(Box{{slitLeft / 2, 7.5}, {slitLeft, 3}, 0.0}));
    const double right = slitLeft + 1;
    scene.shapes.push_back(opaqueWall(Box{{(right + 32) / 2, 7.5}, {32 - right, 3}, 0.0}));
    const RayMarcher marcher(rasterize(scene).value());
    double open = 0;
    const double dx = 1.0 / 64;
    for (double x = 8 + dx / 2; x < 24; x += dx) {
        open += marcher.segment({x, 2.0}, {x, 14.0}).transmittance.r * dx;
    }
    return open;
}

TEST(ThinOccluders, SlitsInThickWallsStayOpen) {
    const double aligned = slitOpenWidth(15.0), straddling = slitOpenWidth(15.5);
    std::printf("1 px slit in a 3 px wall lets through %.3f px aligned, %.3f px straddling\n",
                aligned, straddling);
    EXPECT_NEAR(aligned, 1.0, 0.01);
    // Two half-covered columns of 3 px: 0.5^3 each (coverage as opacity,
    // docs/algorithms/pixel-medium.md §3).
    EXPECT_NEAR(straddling, 2 * 0.125, 0.01);
}

}  // namespace
}  // namespace luxel::gi2d
