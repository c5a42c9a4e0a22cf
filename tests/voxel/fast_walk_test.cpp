// castRay's CPU loop (src/voxel/fast_walk.h) against the shared kernel it stands in for
// (castRayShared): the same Hit, field by field and loop count included, ray by ray, on worlds
// and rays built to tie at edges and corners, to jump over boxes of every size and to run into
// tMax and the step cap; occluded() against castRay's hit; and the SIMD batch calls
// (src/voxel/cast_stream.cpp) against castRay and occluded, ray by ray.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "luxel/voxel/dda.h"
#include "terrain_with_blocks.h"
#include "voxel/fast_walk.h"
#include "voxel/lane_walk.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kStone{128, 128, 128, 255};

void expectIdentical(const Hit& a, const Hit& b, int ray) {
    ASSERT_EQ(a.hit, b.hit) << "ray " << ray;
    EXPECT_EQ(a.capped, b.capped) << "ray " << ray;
    EXPECT_EQ(a.steps, b.steps) << "ray " << ray;
    EXPECT_EQ(a.voxel, b.voxel) << "ray " << ray;
    EXPECT_EQ(a.normal, b.normal) << "ray " << ray;
    EXPECT_EQ(a.t, b.t) << "ray " << ray;
    EXPECT_EQ(a.point, b.point) << "ray " << ray;
    EXPECT_EQ(a.u, b.u) << "ray " << ray;
    EXPECT_EQ(a.v, b.v) << "ray " << ray;
}

// Terrain with floating blocks and a cave-free sky: long empty boxes above, dense bricks below.
VoxelWorld terrain(Int3 size, std::uint64_t seed) {
    return terrainWithBlocks(size, seed, 60, 0.03, size.y / 2);
}

struct Counts {
    int hits = 0, capped = 0;
};

Counts compare(const VoxelWorld& world, const std::vector<Ray>& rays, double tMax = kInfinity,
               int stepCap = 0) {
    Counts counts;
    std::vector<Hit> batch(rays.size());
    std::vector<std::uint8_t> blocked(rays.size());
    castRayBatch(world, rays, batch, tMax, stepCap);
    occludedBatch(world, rays, blocked, tMax, stepCap);
    const std::vector<Hit> lanes = castRayLanes(world, rays, tMax, stepCap);
    for (int i = 0; i < static_cast<int>(rays.size()); ++i) {
        const Hit mine = castRay(world, rays[i], tMax, stepCap);
        const Hit reference = castRayShared(world, rays[i], tMax, stepCap);
        expectIdentical(mine, reference, i);
        expectIdentical(batch[i], reference, i);
        expectIdentical(lanes[i], reference, i);
        EXPECT_EQ(occluded(world, rays[i], tMax, stepCap), reference.hit) << "ray " << i;
        EXPECT_EQ(blocked[i] != 0, reference.hit) << "ray " << i;
        counts.hits += reference.hit;
        counts.capped += reference.capped;
    }
    return counts;
}

TEST(VoxelFastWalk, RandomRaysMatchTheSharedKernel) {
    const Int3 size{96, 64, 80};
    const VoxelWorld world = terrain(size, 9);
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Ray> rays;
    for (int i = 0; i < 20000; ++i) {
        Vec3d origin, direction;
        const double spread = i % 10 == 0 ? 300.0 : 8.0;
        for (int a = 0; a < 3; ++a) {
            origin[a] = -spread + unit(rng) * (size[a] + 2.0 * spread);
            direction[a] = unit(rng) * 2.0 - 1.0;
            if (i % 7 == 0 && a == i % 3) direction[a] = (i % 2) ? 0.0 : -0.0;
            if (i % 11 == 0 && a == (i + 1) % 3) direction[a] = 1e-9 * (unit(rng) - 0.5);
        }
        rays.push_back({origin, direction});
    }
    const Counts counts = compare(world, rays);
    EXPECT_GT(counts.hits, 5000);
}

// Origins on a quarter grid and power-of-two direction components: every boundary t is exact, so
// rays cross edges and corners exactly (ties inside steps and inside jumps).
TEST(VoxelFastWalk, DyadicRaysTieAtEdgesAndCorners) {
    const Int3 size{64, 48, 72};
    const VoxelWorld world = terrain(size, 4);
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> coord(-4, 75), pick(0, 10);
    const double dyadic[] = {0.0, 0.25, -0.25, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0, 4.0, -4.0};
    std::vector<Ray> rays;
    for (int i = 0; i < 30000; ++i) {
        const Vec3d origin{coord(rng) + 0.25 * (i % 4), coord(rng) * 0.75,
                           coord(rng) + 0.5 * (i % 3)};
        Vec3d direction{dyadic[pick(rng)], dyadic[pick(rng)], dyadic[pick(rng)]};
        if (direction == Vec3d{}) direction.y = -1.0;
        rays.push_back({origin, direction});
    }
    const Counts counts = compare(world, rays);
    EXPECT_GT(counts.hits, 5000);
}

// Secondary rays from the hits (on the faces, as shadows and reflections start), with tMax and
// the step cap cutting some of them short.
TEST(VoxelFastWalk, SecondaryRaysTMaxAndStepCap) {
    const Int3 size{80, 64, 80};
    const VoxelWorld world = terrain(size, 12);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Ray> secondary;
    for (int i = 0; i < 6000; ++i) {
        const Ray primary{{unit(rng) * 80, 70.0, unit(rng) * 80},
                          {unit(rng) - 0.5, -unit(rng), unit(rng) - 0.5}};
        const Hit hit = castRayShared(world, primary);
        if (!hit.hit) continue;
        secondary.push_back({hit.point, {unit(rng) - 0.5, unit(rng), unit(rng) - 0.5}});
        secondary.push_back({hit.point, {0.4, 1.0, 0.3}});
    }
    ASSERT_GT(secondary.size(), 4000u);
    const Counts all = compare(world, secondary);
    EXPECT_GT(all.hits, 500);
    compare(world, secondary, 6.5);
    const Counts capped = compare(world, secondary, kInfinity, 5);
    EXPECT_GT(capped.capped, 100);
}

// Origins at the edges of the start that skips the slab clip (every coordinate in [1, size - 1]):
// on and next to the planes 1 and size - 1, on cell boundaries, just outside that range, with
// zero, signed-zero, tiny and huge direction components, and tMax 0.
TEST(VoxelFastWalk, OriginsDeepInsideStartAsTheSlabClipDoes) {
    const Int3 size{40, 36, 44};
    const VoxelWorld world = terrain(size, 11);
    std::mt19937 rng(21);
    std::uniform_int_distribution<int> pick(0, 1000);
    const auto coordinate = [&](int n) {
        const double edges[] = {0.0, 1.0, 2.0, n - 2.0, n - 1.0, n * 0.5, n * 0.5 + 0.5};
        const double edge = edges[pick(rng) % 7];
        switch (pick(rng) % 4) {
            case 0:
                return edge;
            case 1:
                return std::nextafter(edge, -kInfinity);
            case 2:
                return std::nextafter(edge, kInfinity);
            default:
                return edge + (pick(rng) - 500) * 1e-3;
        }
    };
    const double components[] = {0.0, -0.0, 1.0, -1.0, 0.3, -0.7, 1e-300, -1e-300, 1e300, -2.5};
    std::vector<Ray> rays;
    for (int i = 0; i < 40000; ++i) {
        const Vec3d origin{coordinate(size.x), coordinate(size.y), coordinate(size.z)};
        Vec3d direction{components[pick(rng) % 10], components[pick(rng) % 10],
                        components[pick(rng) % 10]};
        if (direction == Vec3d{}) direction.z = -1.0;
        rays.push_back({origin, direction});
    }
    const Counts counts = compare(world, rays);
    EXPECT_GT(counts.hits, 5000);
    compare(world, rays, 0.0);
}

// The fast loop takes a ray exactly when every non-zero direction component has a finite
// reciprocal (eligible() decides it by comparisons): around 2^-1024, where 1 / d overflows, and
// across the denormals.
TEST(VoxelFastWalk, EligibleExactlyWhenTheReciprocalsAreFinite) {
    const VoxelWorld world = terrain({16, 16, 16}, 1);
    std::vector<double> values{0.0,
                               -0.0,
                               0x1p-1024,
                               0x1p-1023,
                               0x1p-1025,
                               0x1p-1074,
                               std::numeric_limits<double>::min(),
                               std::nan(""),
                               kInfinity,
                               1e-300,
                               1.0,
                               1e300};
    for (int i = 0, n = static_cast<int>(values.size()); i < n; ++i) {
        double down = values[i], up = values[i];
        for (int k = 0; k < 3; ++k) {
            down = std::nextafter(down, 0.0);
            up = std::nextafter(up, 1.0);
            values.push_back(down);
            values.push_back(up);
        }
    }
    for (const double v : values) {
        for (const double d : {v, -v}) {
            const bool finite = d == 0.0 || std::isfinite(1.0 / d);
            for (int a = 0; a < 3; ++a) {
                Vec3d direction{0.5, -0.25, 0.75};
                direction[a] = d;
                EXPECT_EQ(fast::eligible(world, {{8.5, 8.5, 8.5}, direction}), finite)
                    << "component " << a << " = " << d;
            }
        }
    }
}

// Long rays from far away (a jump's floor guess lands far from the cell).
TEST(VoxelFastWalk, FarOriginsMatchTheSharedKernel) {
    const Int3 size{64, 64, 64};
    const VoxelWorld world = terrain(size, 2);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Ray> rays;
    for (int i = 0; i < 4000; ++i) {
        const double far = i % 2 ? 1e5 : 3e7;
        const Vec3d origin{(unit(rng) - 0.5) * far, unit(rng) * far, (unit(rng) - 0.5) * far};
        Vec3d direction;
        for (int a = 0; a < 3; ++a) direction[a] = size[a] * unit(rng) - origin[a];
        rays.push_back({origin, direction});
    }
    const Counts counts = compare(world, rays);
    EXPECT_GT(counts.hits, 1000);
}

// Rays grazing a flat floor with posts on it (solid below y = 5: the floor's top bricks hold one
// solid layer and three empty ones), from the floor's face as shadow and reflection rays start,
// just above it and from outside the world, climbing or sinking slowly, so they walk the empty
// layers of non-empty bricks voxel by voxel for many cells; the world's x and z sizes are not
// multiples of the brick, and tMax and the step cap end many of them inside such bricks. These
// are the rays a jump out of a non-empty brick would serve (docs/algorithms/voxel-traversal.md
// §4.5, "Leaving a non-empty brick in one jump").
TEST(VoxelFastWalk, GrazingRaysInsideNonEmptyBricks) {
    const Int3 size{70, 24, 66};
    VoxelWorld world = VoxelWorld::create(size, 16).value();
    for (int z = 0; z < size.z; ++z) {
        for (int x = 0; x < size.x; ++x) {
            for (int y = 0; y < 5; ++y) world.set(x, y, z, kStone);
        }
    }
    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 40; ++i) {
        const int x = static_cast<int>(unit(rng) * size.x),
                  z = static_cast<int>(unit(rng) * size.z);
        for (int y = 5; y < 5 + 1 + i % 6; ++y) world.set(x, y, z, kStone);
    }
    world.refreshEmptySpace();
    std::vector<Ray> rays;
    const double slopes[] = {0.0, -0.0, 0.01, -0.01, 0.03, 0.0625, -0.0625, 1e-7, 0.25};
    for (int i = 0; i < 20000; ++i) {
        const double angle = unit(rng) * 6.283185307179586;
        const double slope = slopes[i % 9];
        Vec3d direction{std::cos(angle), slope, std::sin(angle)};
        if (i % 5 == 0) direction = {i % 2 ? 1.0 : -0.5, slope, i % 3 ? 0.25 : -1.0};  // ties
        Vec3d origin{unit(rng) * size.x, 5.0, unit(rng) * size.z};
        if (i % 4 == 1) origin.y = 5.0 + unit(rng) * 0.9;
        if (i % 4 == 2) origin.y = std::nextafter(5.0, 6.0);
        if (i % 8 == 3) origin.x = -3.0 - unit(rng) * 20.0;  // entering through the x = 0 face
        if (i % 16 == 7) {
            origin.x = std::floor(origin.x) + 0.5;
            origin.z = std::floor(origin.z);
        }
        rays.push_back({origin, direction});
    }
    const Counts all = compare(world, rays);
    EXPECT_GT(all.hits, 5000);
    // Short reaches ending inside bricks, on cell boundaries and between them.
    for (const double tMax : {0.0, 1.0, 2.5, 3.75, 7.0}) compare(world, rays, tMax);
    for (const int cap : {1, 2, 3, 5, 8, 11}) {
        const Counts capped = compare(world, rays, kInfinity, cap);
        EXPECT_GT(capped.capped, 1000) << "cap " << cap;
    }
}

// Worlds the batch calls leave to castRay (stale distances, fewer than 8 bricks), odd rays (NaN,
// zero, denormal components, negative tMax) and batches of every size around the lane count.
TEST(VoxelFastWalk, BatchEdgeCases) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto randomRays = [&](int n, double extent) {
        std::vector<Ray> rays;
        for (int i = 0; i < n; ++i) {
            rays.push_back({{unit(rng) * extent, unit(rng) * extent, unit(rng) * extent},
                            {unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5}});
        }
        return rays;
    };
    VoxelWorld tiny = VoxelWorld::create({4, 8, 4}, 4).value();  // 2 bricks
    tiny.set(1, 2, 3, kStone);
    tiny.set(2, 6, 1, kStone);
    tiny.refreshEmptySpace();
    compare(tiny, randomRays(3000, 8.0));

    VoxelWorld stale = terrain({40, 40, 40}, 6);
    stale.set(20, 38, 20, kStone);  // a brick gains its first voxel: distances stale
    ASSERT_FALSE(stale.emptySpaceCurrent());
    compare(stale, randomRays(3000, 40.0));

    const VoxelWorld world = terrain({48, 40, 48}, 7);
    std::vector<Ray> odd = randomRays(40, 48.0);
    odd[3].direction = {};
    odd[5].direction.x = std::nan("");
    odd[7].origin.y = kInfinity;
    odd[9].direction = {1e-310, -1.0, 0.5};
    odd[11].direction = {0.0, -1.0, -0.0};
    compare(world, odd);
    compare(world, odd, -1.0);
    for (int n = 0; n <= 40; ++n) compare(world, randomRays(n, 48.0));
}

}  // namespace
}  // namespace luxel::voxel
