// The Felzenszwalb & Huttenlocher transform against brute force, the signed field's sign, the
// conservative lookup's safety for sphere tracing, and region updates against a full rebuild.
#include "luxel/voxel/shadows/distance_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace luxel::voxel {
namespace {

VoxelWorld randomWorld(Int3 size, double density, unsigned seed) {
    VoxelWorld world = std::move(VoxelWorld::create(size, 4).value());
    std::mt19937 rng(seed);
    std::bernoulli_distribution solid(density);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                if (solid(rng)) world.set(x, y, z, Voxel{200, 200, 200, 255});
    world.refreshEmptySpace();
    return world;
}

// Distance from p to the union of the world's solid cubes (brute force).
double trueDistance(const VoxelWorld& world, Vec3d p) {
    double best = 1e30;
    const Int3 s = world.size();
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                if (!world.solid(x, y, z)) continue;
                const double dx = std::max({x - p.x, 0.0, p.x - (x + 1)});
                const double dy = std::max({y - p.y, 0.0, p.y - (y + 1)});
                const double dz = std::max({z - p.z, 0.0, p.z - (z + 1)});
                best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
            }
    return best;
}

TEST(DistanceTransform, EqualsBruteForceOnRandomGrids) {
    std::mt19937 rng(42);
    for (int trial = 0; trial < 40; ++trial) {
        std::uniform_int_distribution<int> side(1, 9);
        const Int3 size{side(rng), side(rng), side(rng)};
        const std::size_t n = static_cast<std::size_t>(size.x) * size.y * size.z;
        std::bernoulli_distribution on(trial % 4 == 0 ? 0.02 : 0.15);
        std::vector<std::uint8_t> feature(n);
        for (auto& f : feature) f = on(rng);
        const std::vector<double> d = squaredDistanceTransform(size, feature);
        for (int z = 0; z < size.z; ++z)
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    double best = kEdtInfinity;
                    for (int k = 0; k < size.z; ++k)
                        for (int j = 0; j < size.y; ++j)
                            for (int i = 0; i < size.x; ++i)
                                if (feature[(static_cast<std::size_t>(k) * size.y + j) * size.x +
                                            i])
                                    best = std::min(best,
                                                    double((x - i) * (x - i) + (y - j) * (y - j) +
                                                           (z - k) * (z - k)));
                    const double got = d[(static_cast<std::size_t>(z) * size.y + y) * size.x + x];
                    if (best >= kEdtInfinity) {
                        ASSERT_GE(got, 1e19) << "trial " << trial;
                    } else {
                        ASSERT_EQ(got, best)
                            << "trial " << trial << " at " << x << "," << y << "," << z;
                    }
                }
    }
}

TEST(DistanceField, SignIsNegativeExactlyInsideSolids) {
    const VoxelWorld world = randomWorld({10, 8, 9}, 0.2, 3);
    const DistanceField field = DistanceField::build(world);
    for (int z = 0; z < 9; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 10; ++x) {
                const float s = field.cell(x, y, z);
                if (world.solid(x, y, z)) {
                    EXPECT_LT(s, 0.0f);
                } else {
                    EXPECT_GT(s, 0.0f);
                }
            }
}

TEST(DistanceField, FlatFaceDistancesAreExact) {
    VoxelWorld world = std::move(VoxelWorld::create({12, 12, 12}, 4).value());
    for (int z = 0; z < 12; ++z)
        for (int x = 0; x < 12; ++x)
            for (int y = 0; y < 3; ++y) world.set(x, y, z, Voxel{1, 1, 1, 255});
    const DistanceField field = DistanceField::build(world);
    EXPECT_FLOAT_EQ(field.cell(5, 3, 5), 0.5f);  // the cell above the floor: centre 0.5 above it
    EXPECT_FLOAT_EQ(field.cell(5, 7, 5), 4.5f);
    EXPECT_NEAR(field.estimate({5.3, 3.0, 6.1}), 0.0, 1e-9);  // zero on the face
    EXPECT_NEAR(field.estimate({5.3, 5.25, 6.1}), 2.25, 1e-9);
}

TEST(DistanceField, ConservativeLookupNeverExceedsTheTrueDistance) {
    const VoxelWorld world = randomWorld({9, 9, 9}, 0.05, 8);
    const DistanceField field = DistanceField::build(world);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-1.0, 10.0);
    int positive = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3d p{u(rng), u(rng), u(rng)};
        const double bound = field.conservative(p);
        ASSERT_LE(bound, trueDistance(world, p) + 1e-9) << p.x << " " << p.y << " " << p.z;
        positive += bound > 0.0;
    }
    EXPECT_GT(positive, 1000);  // and it is useful: most empty points get a positive step
}

TEST(DistanceField, SphereTracingNeverEntersASolidVoxel) {
    const VoxelWorld world = randomWorld({16, 16, 16}, 0.03, 5);
    const DistanceField field = DistanceField::build(world);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0.0, 16.0), n(-1.0, 1.0);
    int steps = 0;
    for (int ray = 0; ray < 300; ++ray) {
        Vec3d p{u(rng), u(rng), u(rng)};
        if (world.solid(int(p.x), int(p.y), int(p.z))) continue;
        Vec3d d{n(rng), n(rng), n(rng)};
        if (length(d) < 1e-3) continue;
        d = normalize(d);
        for (int i = 0; i < 64; ++i) {
            const double h = field.conservative(p);
            if (h <= 1e-3) break;
            // The whole segment stays clear: sample it finely.
            for (int k = 1; k <= 32; ++k) {
                const Vec3d q = p + d * (h * k / 32.0);
                ASSERT_FALSE(
                    world.solid(int(std::floor(q.x)), int(std::floor(q.y)), int(std::floor(q.z))))
                    << "ray " << ray << " step " << i;
            }
            p = p + d * h;
            ++steps;
        }
    }
    EXPECT_GT(steps, 1000);
}

TEST(DistanceField, RegionUpdateEqualsFullRebuild) {
    VoxelWorld world = randomWorld({48, 20, 44}, 0.01, 12);
    DistanceField field = DistanceField::build(world);
    std::mt19937 rng(4);
    for (int edit = 0; edit < 6; ++edit) {
        std::uniform_int_distribution<int> x(0, 40), y(0, 16), z(0, 38);
        const Int3 lo{x(rng), y(rng), z(rng)};
        const Int3 hi{lo.x + 1 + edit, lo.y + 2, lo.z + 3};
        for (int k = lo.z; k < hi.z; ++k)
            for (int j = lo.y; j < hi.y; ++j)
                for (int i = lo.x; i < hi.x; ++i)
                    world.set(i, j, k, edit % 2 ? Voxel{} : Voxel{9, 9, 9, 255});
        field.update(world, lo, hi);
        const DistanceField full = DistanceField::build(world);
        ASSERT_EQ(field.values(), full.values()) << "edit " << edit;
    }
}

}  // namespace
}  // namespace luxel::voxel
