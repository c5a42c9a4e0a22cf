// The GPU path tracer's float kernels (src/gpu/shaders/shared/path_bsdf.h, compiled here as C++)
// against the CPU tracer's double code: GGX's D stays exact for the narrowest lobes where the
// textbook float form cancels, the visible-normal samples are the CPU's directions for the same
// numbers, and the sun's cone directions and containment are SunDisk's.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/shaders/shared/optics.h"
#include "gpu/shaders/shared/path_bsdf.h"
#include "luxel/voxel/path_trace_rng.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/sun_disk.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
namespace sh = luxel::gpu::shared;

constexpr double kPi = 3.14159265358979323846;

TEST(PathBsdfKernels, GgxDistributionStaysExactForNarrowLobes) {
    for (const double alpha : {2e-4, 1e-3, 0.05, 0.5}) {
        for (const double s : {0.0, 0.5, 1.0, 3.0}) {
            const double theta = std::atan(s * alpha);
            const double c = std::cos(theta), sin2 = std::sin(theta) * std::sin(theta);
            const double a2 = alpha * alpha;
            const double f = sin2 + a2 * c * c;
            const double expected = a2 / (kPi * f * f);
            const double got = sh::pathGgxD(float(c), float(sin2), float(alpha));
            EXPECT_NEAR(got / expected, 1.0, 1e-5) << alpha << " " << s;
        }
    }
    // The textbook form 1 + cos^2 (alpha^2 - 1) in float loses the lobe: at alpha = 2e-4 the
    // half vector one alpha off the normal has a cosine that rounds to 1.
    const double alpha = 2e-4, theta = std::atan(alpha);
    const double c = std::cos(theta), a2 = alpha * alpha;
    const double f = std::sin(theta) * std::sin(theta) + a2 * c * c;
    const double expected = a2 / (kPi * f * f);
    EXPECT_GT(std::abs(sh::ggxD(float(c), float(alpha)) / expected - 1.0), 0.5);
}

TEST(PathBsdfKernels, PowerHeuristicMatchesTheCpusAndDoesNotOverflow) {
    for (const double a : {0.0, 1e-3, 1.0, 7.5, 1e4}) {
        for (const double b : {0.0, 1e-3, 2.0, 1e4}) {
            EXPECT_NEAR(sh::pathPowerHeuristic(float(a), float(b)), powerHeuristic(a, b), 1e-6)
                << a << " " << b;
        }
    }
    EXPECT_NEAR(sh::pathPowerHeuristic(1e30f, 1e30f), 0.5f, 1e-6f);
}

TEST(PathBsdfKernels, VisibleNormalSamplesAreTheCpusDirections) {
    ShadeOptions o;
    for (const float roughness : {0.02f, 0.3f, 0.8f}) {
        Material m;
        m.name = "metal";
        m.metallic = 1.0f;
        m.roughness = roughness;
        const Vec3d direction = normalize(Vec3d{0.6, -0.7, 0.3});
        const PathBsdf b = pathBsdf(m, Rgb(0.9f), Int3{0, 1, 0}, direction, o);
        const float alpha = roughness * roughness;
        for (std::uint64_t k = 0; k < 200; ++k) {
            PathRng cpu(7, 3, k), numbers(7, 3, k);
            const BsdfSample sample = sampleBsdf(b, cpu);  // one lobe: two numbers
            const float u1 = numbers.next(), u2 = numbers.next();
            // The face frame of a +y face: tangents x and z.
            const sh::vec3 v(float(b.view.x), float(b.view.z), float(b.cosView));
            const sh::vec3 h = sh::pathGgxVisibleNormal(v, alpha, u1, u2);
            const sh::vec3 hw(h.x, h.z, h.y);
            const sh::vec3 view(float(b.view.x), float(b.view.y), float(b.view.z));
            const sh::vec3 l = normalize(hw * (2.0f * dot(view, hw)) - view);
            if (sample.lobe == BsdfSample::Lobe::None) {
                EXPECT_LE(l.y, 1e-5f) << roughness << " #" << k;
                continue;
            }
            EXPECT_NEAR(l.x, sample.direction.x, 2e-5) << roughness << " #" << k;
            EXPECT_NEAR(l.y, sample.direction.y, 2e-5) << roughness << " #" << k;
            EXPECT_NEAR(l.z, sample.direction.z, 2e-5) << roughness << " #" << k;
            // The density from the sampled half vector against the CPU's from the direction.
            const double pdf = sh::pathGgxMasking(float(b.cosView), alpha) *
                               sh::pathGgxD(h.z, h.x * h.x + h.y * h.y, alpha) / (4.0 * b.cosView);
            EXPECT_NEAR(pdf / sample.pdf, 1.0, 1e-3) << roughness << " #" << k;
        }
    }
}

TEST(PathBsdfKernels, SunConeDirectionsAreSunDisks) {
    const SunDisk sun = SunDisk::make({0.3f, 1.0f, -0.4f}, 2.0 * kPi / 180.0);
    Vec3d t, b;
    sun.frame(t, b);
    const sh::vec3 axis(float(sun.axis.x), float(sun.axis.y), float(sun.axis.z));
    const sh::vec3 tf(float(t.x), float(t.y), float(t.z)), bf(float(b.x), float(b.y), float(b.z));
    PathRng rng(1, 2, 3);
    for (int i = 0; i < 100; ++i) {
        const float u0 = rng.next(), u1 = rng.next();
        const Vec3d cpu = sun.sample(u0, u1);
        const sh::vec3 gpu = sh::pathConeDirection(axis, tf, bf, u0 * float(sun.oneMinusCos),
                                                   2.0f * LUXEL_PATH_PI * u1);
        EXPECT_NEAR(gpu.x, cpu.x, 1e-6) << i;
        EXPECT_NEAR(gpu.y, cpu.y, 1e-6) << i;
        EXPECT_NEAR(gpu.z, cpu.z, 1e-6) << i;
        EXPECT_TRUE(sh::pathConeContains(axis, float(sun.oneMinusCos), gpu));
    }
    // Just outside the disk: 1.02 radii from the axis.
    const Vec3d out = normalize(sun.axis + t * std::tan(1.02 * sun.radius));
    EXPECT_FALSE(sun.contains(out));
    EXPECT_FALSE(sh::pathConeContains(axis, float(sun.oneMinusCos),
                                      sh::vec3(float(out.x), float(out.y), float(out.z))));
    EXPECT_FALSE(sh::pathConeContains(axis, 0.0f, axis));  // a delta sun is never met
}

}  // namespace
