// Emitters keep their exact power when rasterised, at any size and sub-pixel position
// (docs/algorithms/pixel-medium.md §4). The power of a rasterised medium is measured here by an
// integrator of its own: many parallel lines in many directions through the whole canvas, marched
// through the pixels, which shares nothing with the rasteriser's estimate but the ray marcher.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "gi2d/emitter_power.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d {
namespace {

constexpr double kPi = std::numbers::pi;

// Integral over all directed lines of the radiance a medium sends along them (red channel): 90
// directions over the full turn, lines 1/32 px apart at a phase that differs per direction.
double mediumPower(const Medium2D& medium) {
    const RayMarcher marcher(medium);
    const Vec2d centre{0.5 * medium.width(), 0.5 * medium.height()};
    const double reach = 0.5 * std::hypot(medium.width(), medium.height()) + 1;
    constexpr int kDirs = 90;
    const double spacing = 1.0 / 32;
    double sum = 0;
    for (int k = 0; k < kDirs; ++k) {
        const double theta = 2 * kPi * (k + 0.37) / kDirs;
        const Vec2d u{std::cos(theta), std::sin(theta)}, v{-u.y, u.x};
        const double phase = std::fmod(k * 0.7548776662466927, 1.0);
        for (double s = -reach + phase * spacing; s < reach; s += spacing) {
            sum +=
                marcher.segment(centre + v * s - u * reach, centre + v * s + u * reach).radiance.r;
        }
    }
    return sum * spacing * 2 * kPi / kDirs;
}

Medium2D rasterised(const Shape& shape, bool conserve) {
    Scene2D scene{48, 48, {}, {}, {shape}, ""};
    RasterOptions options;
    options.conserveEmitterPower = conserve;
    return rasterize(scene, options).value();
}

Shape opaque(Geometry g) {
    return Shape{"light", std::move(g), Material{Rgb(1.0f), Rgb(kOpaqueAbsorption)}};
}

struct Case {
    const char* name;
    Shape shape;
    double exactPower;  // E * 2 * perimeter for an opaque convex shape
    double thickness;   // px
};

std::vector<Case> cases(Vec2d offset) {
    const Vec2d c = Vec2d{24, 24} + offset;
    std::vector<Case> out;
    for (double r : {0.2, 0.35, 0.7, 1.5, 5.0, 12.0}) {
        out.push_back({"disk", opaque(Circle{c, r}), 2 * 2 * kPi * r, 2 * r});
    }
    // A capsule 0.6 px thick and 8 px long: perimeter 2 * 8 + pi * 0.6.
    out.push_back({"capsule", opaque(Capsule{c - Vec2d{4, 1.3}, c + Vec2d{4, 1.3}, 0.6}),
                   2 * (2 * std::hypot(8.0, 2.6) + kPi * 0.6), 0.6});
    out.push_back({"box", opaque(Box{c, {9, 0.8}, 17.0}), 2 * 2 * (9 + 0.8), 0.8});
    return out;
}

TEST(EmitterPower, ExactIntegralIsTwiceThePerimeterOfAnOpaqueConvexShape) {
    for (const Case& k : cases({0.3, 0.1})) {
        const Material& m = k.shape.material;
        const detail::EmitterPower p =
            detail::emitterPower(k.shape.geometry, m.emission, m.absorption, {}, 16);
        EXPECT_NEAR(p.exact.r / k.exactPower, 1.0, 0.005) << k.name;
    }
}

TEST(EmitterPower, RasterisedEmittersKeepTheirExactPowerAtAnySizeAndPosition) {
    double worstBefore = 0, worstAfter = 0;
    for (Vec2d offset : {Vec2d{0, 0}, Vec2d{0.25, 0.1}, Vec2d{0.5, 0.5}, Vec2d{0.71, 0.33}}) {
        for (const Case& k : cases(offset)) {
            const double before = mediumPower(rasterised(k.shape, false)) / k.exactPower;
            const double after = mediumPower(rasterised(k.shape, true)) / k.exactPower;
            std::printf(
                "%-8s size %5.2f offset (%.2f, %.2f): rasterised / exact power %.4f, "
                "without the factor %.4f\n",
                k.name, k.exactPower / (4 * kPi), offset.x, offset.y, after, before);
            worstBefore = std::max(worstBefore, std::abs(before - 1));
            if (k.thickness <= detail::kFullPowerThickness) {
                EXPECT_NEAR(after, 1.0, 0.01)
                    << k.name << " offset " << offset.x << "," << offset.y;
                worstAfter = std::max(worstAfter, std::abs(after - 1));
            } else {
                // Thick emitters keep their radiance and their rim: a disk of radius R emits
                // about like one of R + 1/2 (docs/algorithms/pixel-medium.md §2).
                EXPECT_GT(after, 1.0);
                EXPECT_LT(after, 1.0 + 0.5 / (0.5 * k.thickness) + 0.01) << k.name;
                continue;
            }
        }
    }
    std::printf("worst power error up to 3 px thick: %.2f%% (without the factor: %.2f%%)\n",
                100 * worstAfter, 100 * worstBefore);
}

// The physical consequence, measured with the reference solver: a light of radius 0.35 px is seen
// from 12-24 px away as bright as the exact disk, mean radiance E asin(R / r) / pi.
TEST(EmitterPower, ASubPixelLightIsAsBrightAsTheExactDiskFromAfar) {
    const double R = 0.35;
    for (Vec2d offset : {Vec2d{0, 0}, Vec2d{0.5, 0.5}}) {
        const Vec2d c = Vec2d{24, 24} + offset;
        const Medium2D medium = rasterised(opaque(Circle{c, R}), true);
        ReferenceOptions options;
        options.rays = 4096;
        const Image fluence = solveReference(medium, options).value();
        double got = 0, exact = 0;
        for (int y = 0; y < 48; ++y) {
            for (int x = 0; x < 48; ++x) {
                const double r = std::hypot(x + 0.5 - c.x, y + 0.5 - c.y);
                if (r < 12 || r > 24) continue;
                got += fluence.at(x, y, 0);
                exact += std::asin(R / r) / kPi;
            }
        }
        std::printf("offset %.1f: annulus fluence / exact disk's %.4f\n", offset.x, got / exact);
        EXPECT_NEAR(got / exact, 1.0, 0.03);
    }
}

}  // namespace
}  // namespace luxel::gi2d
