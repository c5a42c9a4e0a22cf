// Tests for the shared optics kernels (src/gpu/shaders/shared/optics.h): vector Snell against
// trigonometric Snell, the total-internal-reflection test against the critical angle, Fresnel
// bounds and Schlick's error with the right cosine, and energy checks of the specular lobes.
#include "gpu/shaders/shared/optics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace luxel::gpu::shared {
namespace {

constexpr double kPi = std::numbers::pi;

// Unit vector at polar angle theta from +z, azimuth phi.
vec3 direction(double theta, double phi) {
    return vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                float(std::cos(theta)));
}

TEST(Optics, VectorSnellMatchesTrigonometricSnell) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(0.0, 0.5 * kPi);
    std::uniform_real_distribution<double> azimuth(0.0, 2.0 * kPi);
    std::uniform_real_distribution<double> index(1.0, 2.5);
    int refracted = 0;
    for (int i = 0; i < 1000; ++i) {
        const double theta = angle(rng), phi = azimuth(rng);
        const double nI = index(rng), nT = index(rng);
        // Incident direction travelling towards -z onto the surface with normal +z.
        const vec3 in = -direction(theta, phi);
        const vec3 n(0.0f, 0.0f, 1.0f);
        const float cosI = -dot(n, in);
        const float eta = float(nI / nT);
        const float k = opticsRefractK(cosI, eta);
        const double sinT = nI / nT * std::sin(theta);
        ASSERT_EQ(k<0.0f, sinT> 1.0) << theta << " " << nI << " " << nT;
        if (k < 0.0f || sinT > 0.999) continue;
        ++refracted;
        const vec3 t = opticsRefract(in, n, eta, cosI, k);
        const vec3 expected = -direction(std::asin(sinT), phi);
        EXPECT_NEAR(length(t), 1.0f, 1e-5f);
        EXPECT_NEAR(t.x, expected.x, 2e-5f);
        EXPECT_NEAR(t.y, expected.y, 2e-5f);
        EXPECT_NEAR(t.z, expected.z, 2e-5f);
    }
    EXPECT_GT(refracted, 500);
}

TEST(Optics, TotalInternalReflectionExactlyBeyondTheCriticalAngle) {
    // Glass (1.5) to air: theta_c = asin(1 / 1.5) = 41.81 degrees.
    const double critical = std::asin(1.0 / 1.5);
    EXPECT_NEAR(critical * 180.0 / kPi, 41.81, 0.01);
    for (double deg = 0.0; deg < 90.0; deg += 0.1) {
        const double theta = deg * kPi / 180.0;
        if (std::abs(theta - critical) < 1e-4) continue;  // float rounding at the boundary
        const float k = opticsRefractK(float(std::cos(theta)), 1.5f);
        EXPECT_EQ(k<0.0f, theta> critical) << deg;
        EXPECT_EQ(fresnelDielectricExact(float(std::cos(theta)), 1.5f, 1.0f) == 1.0f,
                  theta > critical)
            << deg;
    }
    // Air to glass never reflects totally.
    for (double deg = 0.0; deg <= 90.0; deg += 1.0) {
        EXPECT_GE(opticsRefractK(float(std::cos(deg * kPi / 180.0)), 1.0f / 1.5f), 0.0f);
    }
}

TEST(Optics, ExactFresnelIsAReflectanceWithKnownValues) {
    // Normal incidence: ((n1 - n2) / (n1 + n2))^2 both ways.
    EXPECT_NEAR(fresnelDielectricExact(1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnelDielectricExact(1.0f, 1.5f, 1.0f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnelDielectricExact(1.0f, 1.0f, 1.33f), fresnelF0(1.0f, 1.33f), 1e-6f);
    // Grazing incidence reflects everything; equal indices reflect nothing.
    EXPECT_NEAR(fresnelDielectricExact(0.0f, 1.0f, 1.5f), 1.0f, 1e-6f);
    EXPECT_NEAR(fresnelDielectricExact(0.7f, 1.5f, 1.5f), 0.0f, 1e-6f);
    // Brewster's angle (atan(1.5) from air): r_p = 0, so F = r_s^2 / 2 = 0.0739.
    EXPECT_NEAR(fresnelDielectricExact(float(std::cos(std::atan(1.5))), 1.0f, 1.5f), 0.0739f,
                2e-4f);
    for (int i = 0; i <= 1000; ++i) {
        const float c = i / 1000.0f;
        for (float n : {1.1f, 1.33f, 1.5f, 2.4f}) {
            for (float f :
                 {fresnelDielectricExact(c, 1.0f, n), fresnelDielectricExact(c, n, 1.0f),
                  fresnelDielectricSchlick(c, 1.0f, n), fresnelDielectricSchlick(c, n, 1.0f)}) {
                EXPECT_GE(f, 0.0f);
                EXPECT_LE(f, 1.0f);
            }
        }
    }
}

TEST(Optics, SchlickWithTheRarerSideCosineIsWithinFourHundredths) {
    float worstIn = 0, worstOut = 0, worstWrongCosine = 0;
    for (int i = 0; i <= 9000; ++i) {
        const float cosI = float(std::cos(i / 100.0 * kPi / 180.0));
        worstIn = std::max(worstIn, std::abs(fresnelDielectricSchlick(cosI, 1.0f, 1.5f) -
                                             fresnelDielectricExact(cosI, 1.0f, 1.5f)));
        const float exactOut = fresnelDielectricExact(cosI, 1.5f, 1.0f);
        worstOut =
            std::max(worstOut, std::abs(fresnelDielectricSchlick(cosI, 1.5f, 1.0f) - exactOut));
        // The mistake the kernel avoids: Schlick with the dense side's cosine.
        const float wrong = exactOut == 1.0f ? 1.0f : fresnelSchlick(0.04f, cosI);
        worstWrongCosine = std::max(worstWrongCosine, std::abs(wrong - exactOut));
    }
    EXPECT_LE(worstIn, 0.04f);
    EXPECT_LE(worstOut, 0.04f);
    EXPECT_GT(worstWrongCosine, 0.9f);
}

// Integrates f(l) (N.L) over the hemisphere around +z with a midpoint rule in (cos theta, phi).
template <typename F>
double hemisphereIntegral(F f, int n = 512) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double mu = (i + 0.5) / n;  // cos theta
        const double s = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < n; ++j) {
            const double phi = (j + 0.5) / n * 2.0 * kPi;
            sum += f(vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(mu))) * mu;
        }
    }
    return sum * (1.0 / n) * (2.0 * kPi / n);
}

TEST(Optics, GgxDistributionIsNormalised) {
    // Projected-area normalisation: integral of D(h) (n.h) over the hemisphere = 1.
    for (float roughness : {0.3f, 0.5f, 0.8f, 1.0f}) {
        const float alpha = roughness * roughness;
        const double integral = hemisphereIntegral([&](vec3 h) { return ggxD(h.z, alpha); }, 1024);
        EXPECT_NEAR(integral, 1.0, 0.01) << roughness;
    }
}

TEST(Optics, GgxWhiteFurnaceLosesNoMoreThanSingleScatteringShould) {
    // With F = 1, the directional albedo integral of D Vis (N.L) is <= 1 for every view, and
    // near 1 for smooth-ish surfaces seen from above (single scattering loses energy only at
    // high roughness and grazing views).
    for (float roughness : {0.3f, 0.6f, 1.0f}) {
        const float alpha = roughness * roughness;
        for (double viewDeg : {0.0, 45.0, 75.0}) {
            const vec3 v = direction(viewDeg * kPi / 180.0, 0.0);
            const double albedo = hemisphereIntegral([&](vec3 l) {
                const vec3 h = normalize(l + v);
                return ggxD(h.z, alpha) * ggxSmithVisibility(v.z, l.z, alpha);
            });
            EXPECT_LE(albedo, 1.0) << roughness << " " << viewDeg;
            if (roughness <= 0.3f && viewDeg <= 45.0) {
                EXPECT_GT(albedo, 0.95);
            }
            // alpha = 1 seen from above, analytically: D = 1/pi, Vis = 1 / (2 (N.L + 1)), so
            // the integral is the integral of mu / (1 + mu) over [0, 1] = 1 - ln 2.
            if (roughness == 1.0f && viewDeg == 0.0) {
                EXPECT_NEAR(albedo, 1.0 - std::log(2.0), 1e-3);
            }
        }
    }
}

TEST(Optics, NormalisedBlinnPhongKeepsEnergyNearlyConstant) {
    // Seen from straight above, the reflected fraction of the normalised lobe stays near 1 while
    // the exponent changes a hundredfold (the point of (n + 8) / (8 pi), an approximation: 1.075
    // at n = 8, 1.001 at n = 800).
    const vec3 v(0.0f, 0.0f, 1.0f);
    for (float exponent : {8.0f, 32.0f, 128.0f, 800.0f}) {
        const double albedo = hemisphereIntegral(
            [&](vec3 l) { return blinnPhongLobe(normalize(l + v).z, exponent); }, 1024);
        EXPECT_GT(albedo, 0.85) << exponent;
        EXPECT_LT(albedo, 1.08) << exponent;
    }
    EXPECT_NEAR(blinnPhongExponent(0.1f), 198.0f, 1e-3f);
    EXPECT_EQ(blinnPhongExponent(1.0f), 0.0f);
}

TEST(Optics, ReflectionKeepsTheTangentAndFlipsTheNormal) {
    const vec3 r = opticsReflect(vec3(0.6f, -0.8f, 0.0f), vec3(0.0f, 1.0f, 0.0f));
    EXPECT_FLOAT_EQ(r.x, 0.6f);
    EXPECT_FLOAT_EQ(r.y, 0.8f);
    EXPECT_FLOAT_EQ(r.z, 0.0f);
}

}  // namespace
}  // namespace luxel::gpu::shared
