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
        ASSERT_EQ(field.features(), full.features()) << "edit " << edit;
    }
}

}  // namespace
}  // namespace luxel::voxel

namespace luxel::voxel {
namespace {

// Depth of p inside the solid: distance to the nearest empty cube (outside the world is empty).
double trueDepth(const VoxelWorld& world, Vec3d p) {
    const Int3 s = world.size();
    double best = std::min({p.x, p.y, p.z, s.x - p.x, s.y - p.y, s.z - p.z});
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                if (world.solid(x, y, z)) continue;
                const double dx = std::max({x - p.x, 0.0, p.x - (x + 1)});
                const double dy = std::max({y - p.y, 0.0, p.y - (y + 1)});
                const double dz = std::max({z - p.z, 0.0, p.z - (z + 1)});
                best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
            }
    return best;
}

TEST(DistanceTransform, FeatureTransformNamesANearestFeature) {
    std::mt19937 rng(4);
    for (int trial = 0; trial < 10; ++trial) {
        const Int3 size{5 + trial % 4, 7 - trial % 3, 6};
        const std::size_t n = static_cast<std::size_t>(size.x) * size.y * size.z;
        std::vector<std::uint8_t> feature(n);
        std::bernoulli_distribution on(0.08);
        for (auto& f : feature) f = on(rng);
        std::vector<std::int32_t> nearest;
        const std::vector<double> d = squaredDistanceTransform(size, feature, &nearest);
        for (std::size_t i = 0; i < n; ++i) {
            if (d[i] >= kEdtInfinity) {
                EXPECT_EQ(nearest[i], -1);
                continue;
            }
            const std::int32_t f = nearest[i];
            ASSERT_GE(f, 0);
            ASSERT_TRUE(feature[f]);
            const int a = int(i), b = f;
            const int dx = a % size.x - b % size.x,
                      dy = (a / size.x) % size.y - (b / size.x) % size.y,
                      dz = a / (size.x * size.y) - b / (size.x * size.y);
            EXPECT_EQ(double(dx * dx + dy * dy + dz * dz), d[i]) << i;
        }
    }
}

TEST(DistanceField, SurfaceDistanceMatchesTheCubesByBruteForce) {
    const VoxelWorld world = randomWorld({10, 10, 10}, 0.06, 12);
    const DistanceField field = DistanceField::build(world);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    int outsidePoints = 0, insidePoints = 0, exact = 0, centreExact = 0;
    double worst = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3d p{u(rng), u(rng), u(rng)};
        const bool inside = world.solid(int(p.x), int(p.y), int(p.z));
        const double s = field.surfaceDistance(p);
        if (inside) {
            ++insidePoints;
            const double depth = trueDepth(world, p);
            ASSERT_LE(s, 0.0);
            ASSERT_NEAR(-s, depth, 1e-5) << p.x << " " << p.y << " " << p.z;
            continue;
        }
        const double truth = std::min(trueDistance(world, p), double(DistanceField::kCap));
        ++outsidePoints;
        // Every candidate is a real cube: never nearer than the nearest one.
        ASSERT_GE(s, truth - 1e-5) << p.x << " " << p.y << " " << p.z;
        worst = std::max(worst, s - truth);
        exact += std::abs(s - truth) < 1e-5;
        centreExact += std::abs(field.estimate(p) - truth) < 1e-5;
    }
    EXPECT_GT(insidePoints, 100);
    // Exact almost everywhere (the trilinear centre field is exact only next to flat faces).
    EXPECT_GE(exact, outsidePoints * 99 / 100) << "worst excess " << worst;
    EXPECT_LT(centreExact, outsidePoints / 2);
    EXPECT_LT(worst, 0.6);  // measured 0.49: a nearer cube that none of the 8 cells names
}

TEST(DistanceField, SurfaceDistanceIsExactAtTheEdgesOfAThinPost) {
    // A 1-voxel post: beside its edge the centre field reads sqrt(2) - 1/2 = 0.91 against the true
    // 0.71; the cube distance is exact.
    VoxelWorld world = std::move(VoxelWorld::create({8, 8, 8}, 4).value());
    for (int y = 0; y < 8; ++y) world.set(4, y, 4, Voxel{200, 200, 200, 255});
    world.refreshEmptySpace();
    const DistanceField field = DistanceField::build(world);
    const Vec3d p{3.5 - 0.5, 4.2, 3.5 - 0.5};  // diagonal from the post's (4, 4) edge
    EXPECT_NEAR(field.surfaceDistance(p), std::sqrt(2.0), 1e-6);
    EXPECT_NEAR(field.surfaceDistance({3.5, 4.2, 3.5}), std::sqrt(0.5), 1e-6);
    EXPECT_GT(field.estimate({3.5, 4.2, 3.5}), std::sqrt(0.5) + 0.15);
    EXPECT_NEAR(field.surfaceDistance({4.5, 4.2, 4.3}), -0.3, 1e-6);  // inside: minus the depth
}

}  // namespace
}  // namespace luxel::voxel
