// sunDiskAlong keeps the last sun's disk per thread (solver_sun.h): what it returns is what the
// disk made afresh gives, while the sun changes between calls (among them -0 against 0, which
// give the disk different tangents) and for a delta sun.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "voxel/solver_sun.h"
#include "voxel/sun_disk.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

Rgb freshDiskAlong(Vec3d direction, const ShadeOptions& o) {
    const SunDisk sun = SunDisk::make(o.sunDirection, o.sunAngularRadius);
    return sun.contains(direction) ? sun.radiance(o.sunIrradiance) : Rgb{};
}

bool sameBits(Rgb a, Rgb b) {
    return std::bit_cast<std::uint32_t>(a.r) == std::bit_cast<std::uint32_t>(b.r) &&
           std::bit_cast<std::uint32_t>(a.g) == std::bit_cast<std::uint32_t>(b.g) &&
           std::bit_cast<std::uint32_t>(a.b) == std::bit_cast<std::uint32_t>(b.b);
}

TEST(SunDiskAlong, KeptDiskGivesTheFreshDisksRadiance) {
    std::mt19937 rng(1128);
    std::normal_distribution<float> g;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    // A few suns, asked for in a random order so the kept disk keeps changing.
    ShadeOptions suns[5];
    suns[0].sunDirection = {0.0f, 1.0f, 0.5f};
    suns[1].sunDirection = {-0.0f, 1.0f, 0.5f};
    suns[2].sunDirection = {0.3f, 0.8f, -0.2f};
    suns[2].sunAngularRadius = 0.05;
    suns[3].sunDirection = {0.3f, 0.8f, -0.2f};
    suns[3].sunAngularRadius = 0.0;  // a delta sun: never seen
    suns[4].sunDirection = {0.3f, 0.8f, -0.2f};
    suns[4].sunAngularRadius = 0.2;
    suns[4].sunIrradiance = {1.0f, 2.0f, 3.0f};
    int inside = 0;
    for (int i = 0; i < 100000; ++i) {
        const ShadeOptions& o = suns[std::uniform_int_distribution<int>(0, 4)(rng)];
        const SunDisk disk = SunDisk::make(o.sunDirection, o.sunAngularRadius);
        // Half the directions near the disk's axis (inside or at its rim), half anywhere.
        Vec3d d{g(rng), g(rng), g(rng)};
        if (i & 1) d = disk.axis + d * (disk.radius * u(rng) * 1.5);
        const double len = std::sqrt(dot(d, d));
        if (!(len > 1e-9)) continue;
        d = d * (1.0 / len);
        const Rgb want = freshDiskAlong(d, o);
        const Rgb got = sunDiskAlong(d, o);
        ASSERT_TRUE(sameBits(got, want)) << "case " << i;
        inside += want.maxComponent() > 0.0f;
    }
    EXPECT_GT(inside, 10000);  // the disk's radiance is met, not only its zero
}

}  // namespace
