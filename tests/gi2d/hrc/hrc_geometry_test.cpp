// HRC geometry: ray offsets, extension identities, angular weights
// (docs/algorithms/holographic-radiance-cascades.md §2-5).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/ray_tables.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/rng.h"

namespace luxel::gi2d::hrc {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(HrcGeometry, RayOffsetsSpanTheFrustumTwoPixelsApart) {
    for (int n = 0; n < 8; ++n) {
        EXPECT_EQ(rayOffsetY(n, 0), -pow2(n));       // -45 degrees
        EXPECT_EQ(rayOffsetY(n, pow2(n)), pow2(n));  // +45 degrees
        for (int k = 0; k < pow2(n); ++k) EXPECT_EQ(rayOffsetY(n, k + 1) - rayOffsetY(n, k), 2);
        EXPECT_DOUBLE_EQ(rayAngle(n, 0), -kPi / 4);
        EXPECT_DOUBLE_EQ(rayAngle(n, pow2(n)), kPi / 4);
    }
    EXPECT_EQ(rayOffsetY(0, 0), -1);
    EXPECT_EQ(rayOffsetY(0, 1), 1);
}

TEST(HrcGeometry, HalvingRelationAndExtensionEndPoints) {
    for (int n = 1; n < 10; ++n) {
        for (int k = 0; k <= pow2(n); ++k) {
            // v_n(k) = v_{n-1}(lo) + v_{n-1}(hi): both bent paths end where the straight ray does.
            const int lo = k >> 1, hi = (k + 1) >> 1;
            EXPECT_EQ(rayOffsetY(n - 1, lo) + rayOffsetY(n - 1, hi), rayOffsetY(n, k));
            EXPECT_EQ(pow2(n - 1) + pow2(n - 1), pow2(n));
            if (k % 2 == 0) {
                EXPECT_EQ(lo, hi);  // even k: the straight ray itself
                EXPECT_EQ(rayOffsetY(n, k),
                          2 * rayOffsetY(n - 1, k / 2));  // v_n(2j) = 2 v_{n-1}(j)
            }
        }
    }
}

TEST(HrcGeometry, ConeWeightsCoverNinetyDegreesPerFrustumAndTwoPiInAll) {
    for (int n = 0; n < 12; ++n) {
        const std::vector<float> w = coneWeights(n);
        ASSERT_EQ(w.size(), static_cast<std::size_t>(pow2(n + 1)));
        double sum = 0;
        for (float v : w) {
            EXPECT_GT(v, 0.0f);
            sum += v;
        }
        EXPECT_NEAR(sum, kPi / 2, 1e-5) << "level " << n;
        EXPECT_NEAR(4 * sum, 2 * kPi, 4e-5);
    }
    const std::vector<float> w0 = coneWeights(0);
    EXPECT_FLOAT_EQ(w0[0], static_cast<float>(kPi / 4));
    EXPECT_FLOAT_EQ(w0[1], static_cast<float>(kPi / 4));
}

TEST(HrcGeometry, CascadeAndPlaneCounts) {
    EXPECT_EQ(cascadeCount(512), 9);
    EXPECT_EQ(cascadeCount(513), 10);
    EXPECT_EQ(cascadeCount(640), 10);
    EXPECT_EQ(cascadeCount(1), 1);
    EXPECT_EQ(planeCount(640, 0), 640);
    EXPECT_EQ(planeCount(640, 3), 80);
    EXPECT_EQ(planeCount(640, 9), 2);
}

TEST(HrcGeometry, FramesMapEveryCanvasPixelOnce) {
    const int w = 7, h = 5;
    for (int r = 0; r < 4; ++r) {
        const FrustumFrame f = makeFrame(static_cast<Frustum>(r), w, h);
        std::vector<int> hits(w * h, 0);
        for (int v = 0; v < f.rows; ++v) {
            for (int u = 0; u < f.length; ++u) {
                int x, y;
                f.toCanvas(u, v, x, y);
                ASSERT_TRUE(x >= 0 && x < w && y >= 0 && y < h);
                ++hits[y * w + x];
            }
        }
        for (int c : hits) EXPECT_EQ(c, 1);
    }
    // +x looks along +x: moving along the frame axis moves right on the canvas; -y moves up.
    int x0, y0, x1, y1;
    makeFrame(Frustum::MinusY, w, h).toCanvas(0, 2, x0, y0);
    makeFrame(Frustum::MinusY, w, h).toCanvas(1, 2, x1, y1);
    EXPECT_EQ(x0, x1);
    EXPECT_EQ(y1, y0 - 1);
}

// A random volumetric medium for table tests.
Medium2D randomMedium(int w, int h) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), Rgb()};
    Pcg32 rng(7);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            m.absorption.setRgb(x, y, Rgb(rng.nextFloat() * 0.4f, rng.nextFloat() * 0.2f, 0.1f));
            m.emission.setRgb(x, y, Rgb(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()));
        }
    }
    return m;
}

TEST(HrcRayTables, ExtendedEvenRaysEqualTracedStraightRays) {
    // With T_{n-1} traced exactly, T_n for even k by extension is the straight ray split at the
    // midpoint plane, so it must match the same ray marched exactly (up to binary16 storage).
    const Medium2D medium = randomMedium(32, 24);
    const RayMarcher marcher(medium);
    for (int n = 1; n < 5; ++n) {
        RayTables traced, extended;
        traced.reset(32, 24, n + 1);
        extended.reset(32, 24, n + 1);
        traceBaseLevels(traced, marcher, n + 1);
        traceBaseLevels(extended, marcher, n);
        extendLevels(extended, n);
        for (int p = 0; p < traced.planes(n); ++p) {
            for (int k = 0; k <= pow2(n); k += 2) {
                for (int y = 0; y < 24; ++y) {
                    // The halves of a ray leaving the frame read empty space: compare rays that
                    // stay inside.
                    const int yEnd = y + rayOffsetY(n, k);
                    if (yEnd < 0 || yEnd >= 24 || (p + 1) * pow2(n) > 32) continue;
                    const Interval a = traced.get(n, p, y, k), b = extended.get(n, p, y, k);
                    for (int c = 0; c < 3; ++c) {
                        EXPECT_NEAR(a.radiance[c], b.radiance[c], 4e-3 * (1 + a.radiance[c]))
                            << n << " " << p << " " << y << " " << k;
                        EXPECT_NEAR(a.transmittance[c], b.transmittance[c], 4e-3);
                    }
                }
            }
        }
    }
}

TEST(HrcRayTables, ExtendedOddRaysAverageTwoBentPathsAroundTheStraightRay) {
    // In a uniform medium a path of length l gives T = exp(-sigma l). Bent paths are never shorter
    // than the straight ray. Extending from 3 traced levels (the paper) keeps them within a few
    // percent of it; extending from c0 builds every ray from 45-degree steps, 2^n sqrt(2) long.
    Medium2D medium{Image(128, 128, 3), Image(128, 128, 3), Rgb()};
    const float sigma = 0.02f;
    medium.absorption.fill(sigma);
    const RayMarcher marcher(medium);
    for (int traced : {1, 3}) {
        RayTables tables;
        tables.reset(128, 128, 7);
        traceBaseLevels(tables, marcher, traced);
        extendLevels(tables, traced);
        for (int n = traced; n < 7; ++n) {
            for (int k = 1; k < pow2(n); k += 2) {
                const double straight = std::hypot(pow2(n), rayOffsetY(n, k));
                const double depth = -std::log(tables.get(n, 0, 64, k).transmittance.x) / sigma;
                EXPECT_GE(depth, straight * 0.995) << traced << ": " << n << "," << k;
                const double longest = traced == 1 ? pow2(n) * std::sqrt(2.0) : straight * 1.05;
                EXPECT_LE(depth, longest * 1.005) << traced << ": " << n << "," << k;
            }
        }
    }
}

TEST(HrcRayTables, MemoryEstimateMatchesAllocation) {
    // (N_c + 3) D^2 entries per frustum, 12 bytes each
    // (docs/algorithms/holographic-radiance-cascades.md §8.1).
    const std::uint64_t bytes = RayTables::bytesFor(1024, 1024, 10);
    EXPECT_NEAR(static_cast<double>(bytes) / (1024.0 * 1024 * 12), 12.0, 0.05);
}

// §5.1: the rows an upper read blends keep a uniform field unchanged, the weight towards the
// bisector halves per cascade from 1/2 (the linear interpolation at cascade 0), and the far probe
// of an even plane reads 1/4, 1/2, 1/4 there.
TEST(HrcGeometry, UpperReadsBlendRowsWithWeightsSummingToOne) {
    namespace sh = gpu::shared;
    const sh::vec3 one(1.0f), zero(0.0f);
    for (int n = 0; n < 28; ++n) {
        const float a = sh::hrcSecondRowWeight(n);
        // 7/16 at cascade 0, halving from 1/4 above (§5.1 with §3.1's depth scale).
        EXPECT_FLOAT_EQ(a, n == 0 ? 0.4375f : std::ldexp(1.0f, -(n + 1)));
        EXPECT_FLOAT_EQ(sh::hrcBlendTwoRows(one, one, a).x, 1.0f);
        EXPECT_FLOAT_EQ(sh::hrcBlendThreeRows(one, one, one, a).x, 1.0f);
        EXPECT_FLOAT_EQ(sh::hrcBlendTwoRows(one, one, sh::hrcNearRowWeight(n)).x, 1.0f);
    }
    EXPECT_FLOAT_EQ(sh::hrcBlendThreeRows(one, zero, zero, 0.5f).x, 0.25f);
    EXPECT_FLOAT_EQ(sh::hrcBlendThreeRows(zero, one, zero, 0.5f).x, 0.5f);
    EXPECT_FLOAT_EQ(sh::hrcBlendThreeRows(zero, zero, one, 0.5f).x, 0.25f);
    EXPECT_EQ(sh::hrcTowardsAxis(0), 1);  // the lower side's bisector lies above its ray
    EXPECT_EQ(sh::hrcTowardsAxis(1), -1);
    EXPECT_FLOAT_EQ(sh::hrcNearRowWeight(0), 0.25f);
    EXPECT_FLOAT_EQ(sh::hrcNearRowWeight(1), 0.25f);
    EXPECT_FLOAT_EQ(sh::hrcNearRowWeight(2), 0.0f);
}

TEST(HrcGeometry, CascadeZeroCountsItsSubConesMeanPath) {
    // §3.1: the directions between a frustum edge and its axis cross one pixel column over
    // ln(1 + sqrt 2) / (pi / 4) px on average; cascade 0's diagonal ray over sqrt 2.
    namespace sh = gpu::shared;
    const double meanPath = std::log(1.0 + std::sqrt(2.0)) / (std::numbers::pi / 4);
    EXPECT_NEAR(sh::hrcTracedDepthScale(0, 3), meanPath / std::sqrt(2.0), 1e-6);
    EXPECT_FLOAT_EQ(sh::hrcTracedDepthScale(1, 3), 1.0f);
    EXPECT_FLOAT_EQ(sh::hrcTracedDepthScale(2, 3), 1.0f);
    // Extending from c0: cascade 0's rays build the longer ones and keep their true length.
    EXPECT_FLOAT_EQ(sh::hrcTracedDepthScale(0, 1), 1.0f);
}

}  // namespace
}  // namespace luxel::gi2d::hrc
