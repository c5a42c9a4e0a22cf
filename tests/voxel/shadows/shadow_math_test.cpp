// The shared shadow formulas (shadow_moments.h, soft_shadow.h) against exact answers on depth
// distributions whose lit fraction is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "gpu/shaders/shared/shadow_moments.h"
#include "gpu/shaders/shared/soft_shadow.h"

namespace {

using namespace luxel::gpu::shared;

// A discrete depth distribution: atoms (depth, weight), weights summing to 1.
struct Layers {
    std::vector<float> depth, weight;
    vec4 moments() const {
        vec4 b(0.0f);
        for (std::size_t i = 0; i < depth.size(); ++i) b = b + momentsOfDepth(depth[i]) * weight[i];
        return b;
    }
    // Fraction of the filter region whose occluder is nearer the light than z (the shadowed part).
    float occluded(float z) const {
        float s = 0;
        for (std::size_t i = 0; i < depth.size(); ++i) s += depth[i] < z ? weight[i] : 0.0f;
        return s;
    }
};

Layers randomLayers(std::mt19937& rng) {
    std::uniform_int_distribution<int> count(1, 6);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Layers l;
    const int n = count(rng);
    float total = 0;
    for (int i = 0; i < n; ++i) {
        l.depth.push_back(0.05f + 0.9f * u(rng));
        l.weight.push_back(0.05f + u(rng));
        total += l.weight.back();
    }
    for (float& w : l.weight) w /= total;
    return l;
}

TEST(ShadowMoments, VsmIsAnUpperBoundOnTheLitFraction) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int trial = 0; trial < 5000; ++trial) {
        const Layers l = randomLayers(rng);
        const vec4 b = l.moments();
        const float z = u(rng);
        const float lit = 1.0f - l.occluded(z);
        EXPECT_GE(vsmVisibility(b.x, b.y, z), lit - 1e-4f) << "trial " << trial;
    }
}

TEST(ShadowMoments, VsmMatchesCantelliForTwoAtoms) {
    // Half the texel at depth 0.2, half at 0.6: mean 0.4, variance 0.04. At z = 0.8 the bound is
    // 0.04 / (0.04 + 0.16) = 0.2 (the MRMA design note's formula gives 1 / 0.2 = 5 here).
    const vec4 b = momentsOfDepth(0.2f) * 0.5f + momentsOfDepth(0.6f) * 0.5f;
    EXPECT_NEAR(vsmVisibility(b.x, b.y, 0.8f), 0.2f, 1e-5f);
    EXPECT_EQ(vsmVisibility(b.x, b.y, 0.3f), 1.0f);  // in front of the mean: lit
}

TEST(ShadowMoments, LightBleedReductionIsALinstep) {
    EXPECT_FLOAT_EQ(reduceLightBleed(0.2f, 0.2f), 0.0f);
    EXPECT_FLOAT_EQ(reduceLightBleed(0.6f, 0.2f), 0.5f);
    EXPECT_FLOAT_EQ(reduceLightBleed(1.0f, 0.2f), 1.0f);
    EXPECT_FLOAT_EQ(reduceLightBleed(0.3f, 0.0f), 0.3f);
}

TEST(ShadowMoments, MsmIsALowerBoundOnTheOccludedFraction) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double msmError = 0, vsmError = 0;
    const int trials = 20000;
    for (int trial = 0; trial < trials; ++trial) {
        const Layers l = randomLayers(rng);
        const vec4 b = l.moments();
        const float z = u(rng);
        const float g = clamp(msmShadowIntensity(b, z, LUXEL_MSM_BIAS_FP32), 0.0f, 1.0f);
        ASSERT_LE(g, l.occluded(z) + 1e-3f) << "trial " << trial << " z " << z;
        msmError += std::abs(g - l.occluded(z));
        vsmError += std::abs((1.0f - vsmVisibility(b.x, b.y, z)) - l.occluded(z));
    }
    // Four moments bound the occluded fraction much more tightly than two.
    EXPECT_LT(msmError / trials, 0.6 * vsmError / trials);
}

TEST(ShadowMoments, MsmIsExactAwayFromOneAndTwoAtoms) {
    const vec4 one = momentsOfDepth(0.4f);
    EXPECT_LT(msmShadowIntensity(one, 0.3f, LUXEL_MSM_BIAS_FP32), 1e-3f);
    EXPECT_GT(msmShadowIntensity(one, 0.5f, LUXEL_MSM_BIAS_FP32), 0.98f);
    // 30% of the texel at depth 0.25, 70% at 0.7: between the atoms 30% is shadowed.
    const vec4 two = momentsOfDepth(0.25f) * 0.3f + momentsOfDepth(0.7f) * 0.7f;
    EXPECT_LT(msmShadowIntensity(two, 0.2f, LUXEL_MSM_BIAS_FP32), 1e-3f);
    EXPECT_NEAR(msmShadowIntensity(two, 0.45f, LUXEL_MSM_BIAS_FP32), 0.3f, 0.02f);
    EXPECT_GT(msmShadowIntensity(two, 0.8f, LUXEL_MSM_BIAS_FP32), 0.97f);
}

TEST(ShadowMoments, OptimizedQuantizationRoundTrips) {
    std::mt19937 rng(3);
    float worst = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const vec4 b = randomLayers(rng).moments();
        const vec4 q = msmEncodeOptimized(b);
        for (int i = 0; i < 4; ++i) {
            // The encoded moments of valid distributions lie in [0, 1] (fit for UNORM storage).
            EXPECT_GE(q[i], -1e-4f);
            EXPECT_LE(q[i], 1.0f + 1e-4f);
        }
        const vec4 back = msmDecodeOptimized(q);
        for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(back[i] - b[i]));
    }
    EXPECT_LT(worst, 2e-5f);
}

TEST(ShadowMoments, SixteenBitStorageKeepsVisibilityCloseToFp32) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double sum = 0;
    const int trials = 5000;
    for (int trial = 0; trial < trials; ++trial) {
        const Layers l = randomLayers(rng);
        const vec4 b = l.moments();
        vec4 q = msmEncodeOptimized(b);
        for (int i = 0; i < 4; ++i) q[i] = dequantizeUnorm16(quantizeUnorm16(q[i]));
        const vec4 stored = msmDecodeOptimized(q);
        const float z = u(rng);
        const float v32 = msmVisibility(b, z, LUXEL_MSM_BIAS_FP32);
        const float v16 = msmVisibility(stored, z, LUXEL_MSM_BIAS_16BIT);
        sum += std::abs(v16 - v32);
        // Still a lower bound on the shadow after rounding, with the larger bias.
        EXPECT_GE(v16, 1.0f - l.occluded(z) - 2e-3f) << "trial " << trial;
    }
    EXPECT_LT(sum / trials, 0.02);
}

TEST(SoftShadow, RemapIsASmoothstepOverMinusOneToOne) {
    EXPECT_FLOAT_EQ(sdfShadowVisibility(-1.0f), 0.0f);
    EXPECT_FLOAT_EQ(sdfShadowVisibility(0.0f), 0.5f);
    EXPECT_FLOAT_EQ(sdfShadowVisibility(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(sdfShadowVisibility(3.0f), 1.0f);
}

TEST(SoftShadow, MarchPastAFlatWallEdgeMatchesTheClearanceAngle) {
    // The ray passes a (conceptual) surface at constant clearance c: with h = c at every sample
    // the ratio is c / (w t), so after t the result is min over samples.
    SdfShadowMarch m = sdfShadowBegin(1.0f);
    const float w = 0.2f;
    for (int i = 0; i < 10; ++i) sdfShadowStep(m, 0.5f, 0.5f, w);
    // Aaltonen's estimate with h = ph: y = h / 2, d = h sqrt(3) / 2; the last sample (t = 5.5)
    // has the smallest ratio d / (w (t - y)).
    EXPECT_NEAR(m.res, 0.5f * std::sqrt(3.0f) / 2.0f / (w * (5.5f - 0.25f)), 1e-5f);
    EXPECT_EQ(m.steps, 10);
    EXPECT_NEAR(m.t, 6.0f, 1e-5f);
    SdfShadowMarch inside = sdfShadowBegin(1.0f);
    sdfShadowStep(inside, -0.5f, -0.5f, w);
    EXPECT_EQ(inside.res, -1.0f);  // clamped, and the ray still moves on
    EXPECT_GT(inside.t, 1.0f);
}

TEST(MrmaBlend, WeightIsAPartitionOfUnityAndContinuous) {
    float previous = mrmaWeight(0.0f, 48.0f, 64.0f, true, true, true);
    for (float d = 0.0f; d <= 100.0f; d += 0.01f) {
        const float a = mrmaWeight(d, 48.0f, 64.0f, true, true, true);
        ASSERT_GE(a, 0.0f);
        ASSERT_LE(a, 1.0f);
        ASSERT_LT(std::abs(a - previous), 0.002f) << d;  // no jump across the band
        previous = a;
        const float b = mrmaWeight(d, 48.0f, 64.0f, false, true, true);
        ASSERT_NEAR(a + b, 1.0f, 1e-6f);  // the opposite split mirrors it
    }
    EXPECT_EQ(mrmaWeight(10.0f, 48.0f, 64.0f, true, true, true), 0.0f);   // near: SDF only
    EXPECT_EQ(mrmaWeight(80.0f, 48.0f, 64.0f, true, true, true), 1.0f);   // far: MSM only
    EXPECT_EQ(mrmaWeight(10.0f, 48.0f, 64.0f, true, false, true), 1.0f);  // SDF invalid
    EXPECT_EQ(mrmaWeight(80.0f, 48.0f, 64.0f, true, true, false), 0.0f);  // MSM invalid
}

TEST(MrmaBlend, CombineIsConvexAndHitsItsEnds) {
    EXPECT_FLOAT_EQ(mrmaCombine(0.2f, 0.8f, 0.0f, false), 0.8f);
    EXPECT_FLOAT_EQ(mrmaCombine(0.2f, 0.8f, 1.0f, false), 0.2f);
    EXPECT_FLOAT_EQ(mrmaCombine(0.2f, 0.8f, 0.25f, false), 0.65f);
    EXPECT_FLOAT_EQ(mrmaCombine(0.2f, 0.8f, 0.25f, true), 0.2f);
    EXPECT_FLOAT_EQ(mrmaCombine(0.2f, 0.8f, 0.0f, true), 0.8f);  // outside the band: one method
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) {
        const float v = mrmaCombine(u(rng), u(rng), u(rng), i % 2 == 0);
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
    }
}

}  // namespace
