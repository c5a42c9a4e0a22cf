// The reference solver against closed-form answers that do not depend on its own output
// (docs/algorithms/pixel-medium.md §2). Shapes are rasterised with the production rasteriser.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d {
namespace {

constexpr double kPi = std::numbers::pi;

Shape opaqueCircle(Vec2d centre, double radius, float emission) {
    return Shape{"disk", Circle{centre, radius}, Material{Rgb(emission), Rgb(kOpaqueAbsorption)}};
}

Shape box(Vec2d min, Vec2d max, Rgb emission, Rgb absorption) {
    return Shape{"box", Box{(min + max) * 0.5, max - min, 0.0}, Material{emission, absorption}};
}

Medium2D rasterOrDie(const Scene2D& scene) {
    auto medium = rasterize(scene);
    EXPECT_TRUE(medium.ok()) << (medium.ok() ? "" : medium.error().message());
    return std::move(medium).value();
}

ReferenceOptions manyRays(int rays = 8192) {
    ReferenceOptions o;
    o.rays = rays;
    return o;
}

// Disk of radiance E and radius R in vacuum: mean radiance at distance r is E asin(R / r) / pi.
TEST(ReferenceAnalytic, DiskInVacuumMatchesArcsineLaw) {
    const double R = 48.0, E = 2.0;
    const Vec2d c{64.0, 160.0};
    Scene2D scene{320, 320, {}, {}, {opaqueCircle(c, R, static_cast<float>(E))}, ""};
    const RayMarcher marcher(rasterOrDie(scene));
    for (double ratio : {1.5, 2.0, 3.0, 5.0}) {
        const int x = static_cast<int>(c.x + ratio * R), y = 160;
        const double r = std::hypot(x + 0.5 - c.x, y + 0.5 - c.y);
        const double got = referenceFluenceAt(marcher, x, y, manyRays()).r;
        const double exact = E * std::asin(R / r) / kPi;
        // The anti-aliased edge acts like a disk about half a pixel larger
        // (docs/algorithms/pixel-medium.md §2).
        const double exactHalfPixel = E * std::asin((R + 0.5) / r) / kPi;
        std::printf("disk r/R %.2f: got %.6f exact %.6f (%+.2f%%) R+0.5 %.6f (%+.2f%%)\n", r / R,
                    got, exact, 100 * (got / exact - 1), exactHalfPixel,
                    100 * (got / exactHalfPixel - 1));
        EXPECT_NEAR(got / exact, 1.0, 0.02) << "r/R = " << r / R;
        EXPECT_NEAR(got / exactHalfPixel, 1.0, 0.004) << "r/R = " << r / R;
    }
}

// The same disk, with an opaque half-plane {y < yEdge} drawn over it. From a pixel below the
// edge, a direction sees the light iff its first hit on the circle lies below the edge: the visible
// directions run from the lower tangent to the near intersection of the circle with the edge line.
TEST(ReferenceAnalytic, DiskBehindHalfPlaneMatchesVisibleAngle) {
    const double R = 48.0, E = 1.0, yEdge = 150.0;
    const Vec2d c{64.0, 160.0};
    Scene2D scene{320, 320, {}, {}, {}, ""};
    scene.shapes.push_back(opaqueCircle(c, R, static_cast<float>(E)));
    scene.shapes.push_back(box({-1000, -1000}, {1000, yEdge}, Rgb(0.0f), Rgb(kOpaqueAbsorption)));
    const RayMarcher marcher(rasterOrDie(scene));
    for (double ratio : {2.0, 3.0, 4.5}) {
        const int x = static_cast<int>(c.x + ratio * R), y = 175;
        const Vec2d p{x + 0.5, y + 0.5};
        const Vec2d toCentre = c - p;
        const double dist = length(toCentre);
        const double centreAngle = std::atan2(toCentre.y, toCentre.x);
        const double alpha = std::asin(R / dist);  // half-angle the disk subtends
        // The tangent on the side away from the occluder: its tangent point has the larger y.
        auto tangentPointY = [&](double side) {
            const double a = centreAngle + side * alpha;
            return p.y + std::sin(a) * std::sqrt(dist * dist - R * R);
        };
        const double lowSide = tangentPointY(1.0) > tangentPointY(-1.0) ? 1.0 : -1.0;
        // Circle and edge line meet at x = c.x +- sqrt(R^2 - (yEdge - c.y)^2); the near one.
        const Vec2d meet{c.x + std::sqrt(R * R - (yEdge - c.y) * (yEdge - c.y)), yEdge};
        const Vec2d toMeet = meet - p;
        ASSERT_LT(dot(meet - c, toMeet), 0.0) << "the meeting point must face the pixel";
        const double meetOffset =
            std::remainder(std::atan2(toMeet.y, toMeet.x) - centreAngle, 2 * kPi);
        ASSERT_LT(std::abs(meetOffset), alpha);
        const double visible = std::abs(lowSide * alpha - meetOffset);
        const double exact = E * visible / (2 * kPi);
        const double got = referenceFluenceAt(marcher, x, y, manyRays()).r;
        std::printf("half-plane r/R %.2f: got %.6f exact %.6f (%+.2f%%)\n", dist / R, got, exact,
                    100 * (got / exact - 1));
        EXPECT_NEAR(got / exact, 1.0, 0.015) << "r/R = " << dist / R;
    }
}

// An opaque emissive wall along the top edge behind a uniform absorbing slab: a ray leaving at
// angle theta from the wall normal crosses the slab over d / cos(theta), so
//   F = (1 / 2pi) * integral over the wall's angular extent of E exp(-sigma d / cos(theta)).
TEST(ReferenceAnalytic, AbsorbingSlabFollowsBeerLambertAndItsAngularIntegral) {
    const int w = 256, h = 128;
    const double E = 3.0, sigma = 0.02, wallBottom = 8.0, slabTop = 20.0, slabBottom = 60.0;
    const double d = slabBottom - slabTop;
    Scene2D scene{w, h, {}, {}, {}, ""};
    scene.shapes.push_back(
        box({-4, -4}, {w + 4.0, wallBottom}, Rgb(static_cast<float>(E)), Rgb(kOpaqueAbsorption)));
    scene.shapes.push_back(
        box({-4, slabTop}, {w + 4.0, slabBottom}, Rgb(0.0f), Rgb(static_cast<float>(sigma))));
    const RayMarcher marcher(rasterOrDie(scene));

    // Along the normal: transmittance exp(-sigma d).
    const int px = w / 2, py = 100;
    const RaySegment up = marcher.march({px + 0.5, py + 0.5}, {0.0, -1.0});
    EXPECT_NEAR(up.radiance.r, E * std::exp(-sigma * d), 1e-4 * E);

    // Fluence: the wall spans x in [0, w] (rays leaving the canvas sideways see nothing).
    const double h0 = py + 0.5 - wallBottom;
    const double thetaLeft = std::atan2(px + 0.5, h0), thetaRight = std::atan2(w - px - 0.5, h0);
    const int steps = 200000;
    double integral = 0;
    for (int i = 0; i < steps; ++i) {
        const double theta = -thetaLeft + (thetaLeft + thetaRight) * (i + 0.5) / steps;
        integral += E * std::exp(-sigma * d / std::cos(theta));
    }
    const double exact = integral * (thetaLeft + thetaRight) / steps / (2 * kPi);
    const double got = referenceFluenceAt(marcher, px, py, manyRays()).r;
    std::printf("slab: got %.6f exact %.6f (%+.3f%%)\n", got, exact, 100 * (got / exact - 1));
    EXPECT_NEAR(got / exact, 1.0, 0.001);
}

// A pixel enclosed by a uniform opaque emissive ring of radiance E reads E (normalisation).
TEST(ReferenceAnalytic, PixelInsideEmissiveRingReadsItsRadiance) {
    const float E = 1.75f;
    Scene2D scene{160, 120, {}, {}, {}, ""};
    scene.shapes.push_back(opaqueCircle({80, 60}, 55, E));
    scene.shapes.push_back(Shape{"hole", Circle{{80, 60}, 40}, Material{Rgb(0.0f), Rgb(0.0f)}});
    const RayMarcher marcher(rasterOrDie(scene));
    for (auto [x, y] : {std::pair{80, 60}, {60, 50}, {100, 75}, {80, 25}}) {
        const Rgb f = referenceFluenceAt(marcher, x, y, manyRays(512));
        EXPECT_NEAR(f.r, E, 1e-4 * E) << x << "," << y;
        EXPECT_NEAR(f.g, E, 1e-4 * E);
    }
    // ... and a pixel inside the emitter itself reads E too.
    EXPECT_NEAR(referenceFluenceAt(marcher, 80, 10, manyRays(512)).b, E, 1e-4 * E);
}

}  // namespace
}  // namespace luxel::gi2d
