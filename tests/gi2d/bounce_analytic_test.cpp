// The bounce rule and the converged reference against closed-form answers.
#include <gtest/gtest.h>

#include "bounce_media.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d {
namespace {

BounceResult convergedReference(const Medium2D& medium, int rays, double tolerance) {
    ReferenceOptions ref;
    ref.rays = rays;
    auto result = solveReferenceWithBounces(medium, ref, tolerance);
    EXPECT_TRUE(result.ok());
    return std::move(result).value();
}

// Largest relative deviation from `expected` over the pixels inside the ring.
double worstInside(const Image& fluence, int ring, float expected) {
    double worst = 0;
    for (int y = ring; y < fluence.height() - ring; ++y) {
        for (int x = ring; x < fluence.width() - ring; ++x) {
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(fluence.at(x, y, c) / expected - 1.0));
            }
        }
    }
    return worst;
}

// A closed ring of emission E and reflectance a: every bounce adds a times the last, E / (1 - a).
TEST(BounceAnalytic, ReflectiveRingReadsEOverOneMinusA) {
    for (float a : {0.3f, 0.6f, 0.9f}) {
        Medium2D m = test::emptyBounceMedium(24);
        test::fillRing(m, 2, Rgb(1.0f), Rgb(a));
        const BounceResult r = convergedReference(m, 64, 1e-5);
        EXPECT_TRUE(r.converged) << "a = " << a;
        const double worst = worstInside(r.fluence, 2, 1.0f / (1.0f - a));
        EXPECT_LT(worst, 0.01) << "a = " << a << " after " << r.bounces << " bounces";
    }
}

// Without reflectance the same ring reads E and nothing bounces.
TEST(BounceAnalytic, BlackRingDoesNotBounce) {
    Medium2D m = test::emptyBounceMedium(24);
    test::fillRing(m, 2, Rgb(1.0f), Rgb());
    const BounceResult r = convergedReference(m, 64, 1e-5);
    EXPECT_LT(worstInside(r.fluence, 2, 1.0f), 1e-4);
}

// Uniform emissive fog of albedo a inside a ring of the same emission and reflectance a: the
// whole interior reads E / (1 - a), whatever the fog's optical depth.
TEST(BounceAnalytic, UniformScatteringMediumInRing) {
    for (float a : {0.3f, 0.6f, 0.9f}) {
        for (float sigma : {0.1f, 1.0f}) {
            Medium2D m = test::emptyBounceMedium(24);
            test::fillRect(m, 0, 0, 24, 24, Rgb(1.0f), Rgb(sigma), Rgb(a));
            test::fillRing(m, 2, Rgb(1.0f), Rgb(a));
            const BounceResult r = convergedReference(m, 64, 1e-5);
            EXPECT_LT(worstInside(r.fluence, 2, 1.0f / (1.0f - a)), 0.01)
                << "a = " << a << ", sigma = " << sigma;
        }
    }
}

// An optically thick emissive fog inside black walls: far from the walls it reads E / (1 - a).
TEST(BounceAnalytic, ThickFogCentreReadsEOverOneMinusA) {
    const float a = 0.6f;
    Medium2D m = test::emptyBounceMedium(32);
    test::fillRect(m, 0, 0, 32, 32, Rgb(1.0f), Rgb(3.0f), Rgb(a));
    test::fillRing(m, 2, Rgb(), Rgb());
    const BounceResult r = convergedReference(m, 64, 1e-5);
    EXPECT_NEAR(r.fluence.at(16, 16, 0), 1.0f / (1.0f - a), 0.01 / (1.0f - a));
    // Next to a black wall less comes back.
    EXPECT_LT(r.fluence.at(2, 16, 0), 0.9f / (1.0f - a));
}

// The rule itself: no scattering and no reflectance leaves the emission unchanged, a scattering
// pixel adds albedo * fluence, and a medium without bounce images is one plain solve.
TEST(BounceAnalytic, SourceRule) {
    Medium2D m = test::emptyBounceMedium(4);
    test::fillRect(m, 0, 0, 4, 4, Rgb(0.5f), Rgb(0.1f));
    test::fillRect(m, 1, 1, 2, 2, Rgb(0.5f), Rgb(0.1f), Rgb(0.5f, 0.25f, 0.0f));
    Image fluence(4, 4, 3);
    fluence.fill(2.0f);
    const Image s = bounceSource(m, fluence, m.emission);
    EXPECT_EQ(s.rgb(0, 0), Rgb(0.5f));
    EXPECT_EQ(s.rgb(1, 1), Rgb(1.5f, 1.0f, 0.5f));

    Medium2D plain{m.emission, m.absorption, Rgb()};
    int solves = 0;
    BounceOptions options;
    options.maxBounces = 5;
    auto r = solveWithBounces(
        plain,
        [&](const Medium2D& x) -> Result<Image> {
            ++solves;
            return Image(x.width(), x.height(), 3);
        },
        options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(solves, 1);
    EXPECT_EQ(r->bounces, 0);
}

}  // namespace
}  // namespace luxel::gi2d
