// Procedural generators: determinism by seed, thread-count independence, shapes and validation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "luxel/core/parallel.h"
#include "luxel/voxel/generators.h"
#include "voxel/noise.h"

namespace luxel::voxel {
namespace {

VoxelWorld makeWorld(Int3 size, int chunkSize = 16) {
    return VoxelWorld::create(size, chunkSize).value();
}

TEST(VoxelNoise, DeterministicBoundedAndZeroOnLattice) {
    const GradientNoise a(7), b(7), c(8);
    bool differs = false;
    for (int i = 0; i < 500; ++i) {
        const float x = i * 0.37f - 50, y = i * 0.71f - 20, z = i * 0.13f;
        EXPECT_EQ(a.noise3(x, y, z), b.noise3(x, y, z));
        EXPECT_EQ(a.noise2(x, y), b.noise2(x, y));
        EXPECT_LE(std::abs(a.noise3(x, y, z)), 1.01f);
        EXPECT_LE(std::abs(a.noise2(x, y)), 1.01f);
        EXPECT_LE(std::abs(a.fbm2(x, y, 6, 2.0f, 0.5f)), 1.01f);
        differs |= a.noise3(x, y, z) != c.noise3(x, y, z);
    }
    EXPECT_TRUE(differs);
    EXPECT_EQ(a.noise3(3, -4, 5), 0.0f);
    EXPECT_EQ(a.noise2(-7, 2), 0.0f);
    // Far-away and non-finite coordinates are safe.
    EXPECT_TRUE(std::isfinite(a.noise3(3e9f, -1e12f, 1e30f)));
    EXPECT_EQ(a.noise2(std::numeric_limits<float>::quiet_NaN(), 0), 0.0f);
}

TEST(Terrain, DeterministicBySeed) {
    TerrainOptions o;
    o.caves = true;
    VoxelWorld a = makeWorld({48, 32, 40}), b = makeWorld({48, 32, 40}),
               c = makeWorld({48, 32, 40});
    ASSERT_TRUE(generateTerrain(a, o).ok());
    ASSERT_TRUE(generateTerrain(b, o).ok());
    o.seed = 2;
    ASSERT_TRUE(generateTerrain(c, o).ok());
    EXPECT_TRUE(a == b);
    EXPECT_FALSE(a == c);
}

TEST(Terrain, IndependentOfThreadCount) {
    TerrainOptions o;
    o.caves = true;
    o.seed = 99;
    VoxelWorld one = makeWorld({70, 40, 50}, 8), two = makeWorld({70, 40, 50}, 8);
    {
        ThreadLimit limit(1);
        ASSERT_TRUE(generateTerrain(one, o).ok());
    }
    {
        ThreadLimit limit(2);
        ASSERT_TRUE(generateTerrain(two, o).ok());
    }
    EXPECT_TRUE(one == two);
    EXPECT_EQ(one.solidCount(), two.solidCount());
}

TEST(Terrain, SolidBelowAirAboveAndBands) {
    TerrainOptions o;
    o.seed = 5;
    o.frequency = 0.03;
    VoxelWorld w = makeWorld({64, 64, 64});
    ASSERT_TRUE(generateTerrain(w, o).ok());
    const Int3 s = w.size();
    std::uint64_t recount = 0;
    for (int z = 0; z < s.z; ++z) {
        for (int x = 0; x < s.x; ++x) {
            EXPECT_TRUE(w.solid(x, 0, z));
            EXPECT_FALSE(w.solid(x, s.y - 1, z));
            for (int y = 0; y < s.y; ++y) recount += w.solid(x, y, z);
        }
    }
    EXPECT_EQ(recount, w.solidCount());
    // Some variation: not every column has the same height.
    int minTop = s.y, maxTop = 0;
    for (int x = 0; x < s.x; ++x) {
        int top = 0;
        while (top < s.y && w.solid(x, top, 10)) ++top;
        minTop = std::min(minTop, top);
        maxTop = std::max(maxTop, top);
    }
    EXPECT_GT(maxTop - minTop, 2);
}

TEST(Terrain, CavesRemoveVoxels) {
    TerrainOptions o;
    o.waterLevel = 0;
    o.baseHeight = 0.6;
    VoxelWorld plain = makeWorld({48, 48, 48}), caves = makeWorld({48, 48, 48});
    ASSERT_TRUE(generateTerrain(plain, o).ok());
    o.caves = true;
    o.caveThreshold = 0.1;
    ASSERT_TRUE(generateTerrain(caves, o).ok());
    EXPECT_LT(caves.solidCount(), plain.solidCount());
    EXPECT_GT(caves.solidCount(), plain.solidCount() / 2);
}

TEST(Terrain, RejectsBadOptions) {
    VoxelWorld w = makeWorld({8, 8, 8});
    auto expectError = [&](TerrainOptions o, const std::string& text) {
        const Status s = generateTerrain(w, o);
        ASSERT_FALSE(s.ok()) << text;
        EXPECT_NE(s.error().message().find(text), std::string::npos) << s.error().message();
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    TerrainOptions o;
    o.frequency = nan;
    expectError(o, "frequency must be in (0, 1], got nan");
    o = {};
    o.baseHeight = -0.5;
    expectError(o, "baseHeight must be in [0, 1], got -0.5");
    o = {};
    o.amplitude = std::numeric_limits<double>::infinity();
    expectError(o, "amplitude");
    o = {};
    o.octaves = 0;
    expectError(o, "octaves must be in [1, 16], got 0");
    o = {};
    o.octaves = 1000;
    expectError(o, "octaves");
    o = {};
    o.lacunarity = 100;
    expectError(o, "lacunarity");
    o = {};
    o.gain = 0;
    expectError(o, "gain");
    o = {};
    o.caveThreshold = nan;
    expectError(o, "caveThreshold");
    o = {};
    o.caveFrequency = -1;
    expectError(o, "caveFrequency");
    o = {};
    o.waterLevel = 2;
    expectError(o, "waterLevel");
    o = {};
    o.steepSlope = -3;
    expectError(o, "steepSlope");
    EXPECT_EQ(w.solidCount(), 0u);  // nothing written on error
}

TEST(VoxelGenerators, RandomFillDensityAndDeterminism) {
    VoxelWorld a = makeWorld({40, 40, 40}, 8), b = makeWorld({40, 40, 40}, 8),
               c = makeWorld({40, 40, 40}, 8);
    const double density = 0.3;
    {
        ThreadLimit limit(1);
        ASSERT_TRUE(fillRandom(a, density, 11).ok());
    }
    {
        ThreadLimit limit(2);
        ASSERT_TRUE(fillRandom(b, density, 11).ok());
    }
    ASSERT_TRUE(fillRandom(c, density, 12, Voxel{1, 2, 3, 255}).ok());
    EXPECT_TRUE(a == b);
    EXPECT_FALSE(a == c);
    // Binomial: n = 64000, sd = sqrt(n p (1 - p)) ~ 116; allow 6 sd.
    const double n = 40.0 * 40 * 40, mean = n * density,
                 sd = std::sqrt(n * density * (1 - density));
    EXPECT_NEAR(static_cast<double>(a.solidCount()), mean, 6 * sd);
    EXPECT_NEAR(static_cast<double>(c.solidCount()), mean, 6 * sd);
    const Voxel fixed{1, 2, 3, 255};
    for (int x = 0; x < 40; ++x) {
        if (c.solid(x, 0, 0)) {
            EXPECT_EQ(c.get(x, 0, 0), fixed);
        }
    }
    // Extremes and bad densities.
    ASSERT_TRUE(fillRandom(a, 1.0, 3).ok());
    EXPECT_EQ(a.solidCount(), 64000u);
    ASSERT_TRUE(fillRandom(a, 0.0, 3).ok());
    EXPECT_EQ(a.solidCount(), 0u);
    const Status bad = fillRandom(a, std::numeric_limits<double>::quiet_NaN(), 3);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("density must be in [0, 1], got nan"), std::string::npos);
    EXPECT_FALSE(fillRandom(a, -0.1, 3).ok());
    EXPECT_FALSE(fillRandom(a, 1.5, 3).ok());
}

TEST(VoxelGenerators, SphereVolume) {
    VoxelWorld w = makeWorld({64, 64, 64});
    const float r = 20.0f;
    addSphere(w, {32.0f, 32.0f, 32.0f}, r, Voxel{255, 0, 0, 255});
    const double expected = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    // The voxelised ball differs from the ball by about its surface area times a fraction of a
    // voxel; 2% is generous at r = 20.
    EXPECT_NEAR(static_cast<double>(w.solidCount()), expected, 0.02 * expected);
    EXPECT_TRUE(w.solid(32, 32, 32));
    EXPECT_TRUE(w.solid(32, 51, 32));   // centre at 51.5: distance 19.5
    EXPECT_FALSE(w.solid(32, 52, 32));  // 20.5
    // Clipped at the border, NaN and negative radius do nothing, a = 0 carves.
    addSphere(w, {0, 0, 0}, 5, Voxel{0, 255, 0, 255});
    EXPECT_TRUE(w.solid(0, 0, 0));
    const std::uint64_t before = w.solidCount();
    addSphere(w, {10, 10, 10}, std::numeric_limits<float>::quiet_NaN(), Voxel{0, 0, 255, 255});
    addSphere(w, {10, 10, 10}, -3, Voxel{0, 0, 255, 255});
    addSphere(w, {std::numeric_limits<float>::infinity(), 0, 0}, 3, Voxel{0, 0, 255, 255});
    EXPECT_EQ(w.solidCount(), before);
    addSphere(w, {32, 32, 32}, 1e30f, Voxel{});
    EXPECT_EQ(w.solidCount(), 0u);
}

TEST(VoxelGenerators, BoxIsClipped) {
    VoxelWorld w = makeWorld({16, 16, 16}, 4);
    addBox(w, {2, 3, 4}, {5, 7, 10}, Voxel{9, 9, 9, 255});
    EXPECT_EQ(w.solidCount(), 3u * 4 * 6);
    EXPECT_TRUE(w.solid(2, 3, 4));
    EXPECT_FALSE(w.solid(5, 3, 4));
    addBox(w, {-100, -100, -100}, {100, 1, 100}, Voxel{1, 1, 1, 255});
    EXPECT_EQ(w.solidCount(), 3u * 4 * 6 + 16 * 16);
    addBox(w, {5, 5, 5}, {2, 2, 2}, Voxel{1, 1, 1, 255});  // empty box
    EXPECT_EQ(w.solidCount(), 3u * 4 * 6 + 16 * 16);
}

}  // namespace
}  // namespace luxel::voxel
