// mediumEntryTransmission computes pathBsdf's transmission lobe weight alone (solver_sun.h,
// docs/algorithms/voxel-radiance-cascades.md §4.2): the same float, bit for bit, as the full
// model gives, for random materials, faces and directions under both Fresnel models, with
// refraction on and off.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "voxel/path_trace_bsdf.h"
#include "voxel/solver_sun.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

// Often one of the ends of [lo, hi] (the shortcut's and the model's special cases), else uniform.
float pick(std::mt19937& rng, float lo, float hi) {
    const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
    if (kind == 0) return lo;
    if (kind == 1) return hi;
    return std::uniform_real_distribution<float>(lo, hi)(rng);
}

Vec3d randomDirection(std::mt19937& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const Vec3d d{g(rng), g(rng), g(rng)};
        const double len = std::sqrt(dot(d, d));
        if (len > 1e-6) return d * (1.0 / len);
    }
}

TEST(MediumEntry, TransmissionAloneIsPathBsdfsToTheBit) {
    constexpr Int3 kNormals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    std::mt19937 rng(20261128);
    int nonZero = 0;
    for (int i = 0; i < 200000; ++i) {
        Material m;
        m.metallic = pick(rng, 0.0f, 1.0f);
        m.roughness = pick(rng, 0.0f, 1.0f);
        m.ior = pick(rng, 1.0f, 4.0f);
        m.transmission = pick(rng, 0.0f, 1.0f);
        ShadeOptions o;
        o.fresnel =
            (i & 1) ? ShadeOptions::FresnelModel::Exact : ShadeOptions::FresnelModel::Schlick;
        o.refraction = (i % 7) != 0;
        const Int3 normal = kNormals[std::uniform_int_distribution<int>(0, 5)(rng)];
        // Mostly entering the face (against its normal), sometimes grazing or leaving it.
        Vec3d d = randomDirection(rng);
        const Vec3d n{double(normal.x), double(normal.y), double(normal.z)};
        if ((i % 5) != 0 && dot(d, n) > 0.0) d = -d;
        const float want = pathBsdf(m, Rgb(1.0f), normal, d, o).transmission;
        const float got = mediumEntryTransmission(m, normal, d, o);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(got), std::bit_cast<std::uint32_t>(want))
            << "case " << i << ": metallic " << m.metallic << " ior " << m.ior << " transmission "
            << m.transmission << " got " << got << " want " << want;
        nonZero += want > 0.0f;
    }
    // The cases are not all the trivial zero.
    EXPECT_GT(nonZero, 50000);
}

}  // namespace
