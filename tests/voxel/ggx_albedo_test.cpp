// The GGX directional albedo table (src/voxel/ggx_albedo.h) the real-time solvers' split-sum
// specular uses: its quadrature against finer rules, a known value, and the path tracer's own GGX
// sampling (the Monte Carlo estimate the table was once filled with) within that estimate's noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "voxel/ggx_albedo.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using luxel::voxel::test::ggxOnlyLobe;

constexpr int kGrid = 24;  // the table's entries per axis, at i / (kGrid - 1)

TEST(GgxAlbedo, QuadratureAgreesWithFinerRulesAndAKnownValue) {
    double worst = 0.0;
    for (const double cosView : {1e-4, 0.01, 0.05, 0.2, 0.5, 1.0})
        for (const double alpha : {1e-4, 0.02, 0.0435, 0.1, 0.25, 0.5, 1.0}) {
            const double table = integrateDirectionalAlbedoGgx(cosView, alpha);
            const double fine = integrateDirectionalAlbedoGgx(cosView, alpha, 64, 48);
            worst = std::max(worst, std::abs(table - fine));
            EXPECT_NEAR(table, fine, 1e-4) << "cos " << cosView << " alpha " << alpha;
            EXPECT_LE(fine, 1.0 + 1e-9);
            EXPECT_GT(fine, 0.3);
        }
    std::printf("GGX albedo: the table's rule within %.2e of a finer one\n", worst);
    // Roughness 0.5 seen from above (path_trace_materials_test.cpp's quadrature in theta, phi),
    // and a grazing view (the midpoint rule with 256 x 1024 points over the unit square of the
    // visible-normal sampling gives 0.999604).
    EXPECT_NEAR(directionalAlbedoGgx(1.0, 0.25), 0.9158, 1e-3);  // bilinear between entries
    EXPECT_NEAR(integrateDirectionalAlbedoGgx(1.0, 0.25), 0.9158, 1.5e-4);
    EXPECT_NEAR(integrateDirectionalAlbedoGgx(1e-4, 9.0 / 23.0), 0.999604, 5e-5);
    // A near-mirror loses nothing to masking.
    EXPECT_NEAR(directionalAlbedoGgx(0.7, 0.0), 1.0, 1e-6);
}

TEST(GgxAlbedo, EveryEntryIsThePathTracersSamplingWithinItsNoise) {
    // The table at its own nodes against 4096 GGX samples of the path tracer per entry (the
    // estimate it replaced, same seeds): nearly all within 3 standard errors, all within 5 and
    // 2e-4. (Seen at the horizon, a few of the 4096 samples fall below it, so there the
    // samples' own standard error is a poor measure: 0.999766 +- 0.000021 at alpha 9/23,
    // where the quadratures agree on 0.99960.)
    int within3 = 0;
    double worstSigmas = 0.0, worstAbsolute = 0.0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const double cosView = std::max(double(i) / (kGrid - 1), 1e-4);
            const double alpha = std::max(double(j) / (kGrid - 1), double(kMirrorAlpha));
            const PathBsdf b = ggxOnlyLobe(cosView, alpha);
            PathRng rng(0x5eed, std::uint64_t(i * kGrid + j), 0);
            const int n = 4096;
            double sum = 0.0, squares = 0.0;
            for (int k = 0; k < n; ++k) {
                const BsdfSample s = sampleBsdf(b, rng);
                const double w = s.lobe == BsdfSample::Lobe::Specular ? s.weight.r : 0.0;
                sum += w, squares += w * w;
            }
            const double mean = sum / n;
            const double se = std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1));
            const double table =
                directionalAlbedoGgx(double(i) / (kGrid - 1), double(j) / (kGrid - 1));
            const double sigmas = std::abs(table - mean) / (se + 1e-6);
            within3 += sigmas <= 3.0;
            worstSigmas = std::max(worstSigmas, sigmas);
            worstAbsolute = std::max(worstAbsolute, std::abs(table - mean));
            EXPECT_LE(std::abs(table - mean), 5.0 * se + 2e-4)
                << "cos " << cosView << " alpha " << alpha << ": table " << table << ", sampled "
                << mean << " +- " << se;
        }
    std::printf(
        "GGX albedo: %d of %d entries within 3 standard errors of the sampled estimate, worst "
        "%.2f (%.2e)\n",
        within3, kGrid * kGrid, worstSigmas, worstAbsolute);
    EXPECT_GE(within3, kGrid * kGrid * 98 / 100);
}

}  // namespace
