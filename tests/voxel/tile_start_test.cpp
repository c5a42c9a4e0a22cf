// The camera sub-tiles' starts in SIMD lanes (startAtPlane, src/voxel/tile_start.h) against the
// one-ray start and jump that fast::traverse<true> takes (voxelStart, then jumpToPlane), state
// for state and bit for bit, on every Highway target this CPU runs: rays from outside aimed at the
// world, missing it, grazing its faces, edges and corners, dyadic directions from origins on cell
// and brick planes (exact ties), zero, signed-zero and denormal components, origins inside, tMax
// before and after the plane. Also the tiles' bounds read once (tileRays of the sub-tiles,
// merged) against the tile read whole (docs/algorithms/voxel-traversal.md §4.6).
#include <gtest/gtest.h>

#include <hwy/targets.h>

#include <cstring>
#include <random>
#include <vector>

#include "luxel/voxel/camera.h"
#include "terrain_with_blocks.h"
#include "voxel/fast_walk.h"
#include "voxel/skip_jump.h"
#include "voxel/tile_start.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;
using stream::PlaneStart;

VoxelWorld world() {
    return terrainWithBlocks({150, 90, 134}, 21, 80, 0.03, 50);
}

bool same(double a, double b) {
    return std::memcmp(&a, &b, sizeof(double)) == 0;
}

// What traverse<true> makes of the ray before its loop: the kind and, when it walks on, the state.
PlaneStart reference(const VoxelWorld& w, const Ray& ray, stream::Skip skip, double tMax,
                     shared::VoxelWalk& walk) {
    walk.o = toShared(ray.origin);
    walk.d = toShared(ray.direction);
    walk.inv = shared::dvec3(1.0 / walk.d.x, 1.0 / walk.d.y, 1.0 / walk.d.z);
    const Int3 size = w.size();
    walk.size = shared::ivec3(size.x, size.y, size.z);
    if (fast::deepInside(walk)) return PlaneStart::OneRay;
    if (!shared::voxelStart(walk, tMax)) return PlaneStart::StartMissed;
    switch (stream::jumpToPlane(walk, skip, size, tMax)) {
        case stream::SkipResult::Missed:
            return PlaneStart::JumpMissed;
        case stream::SkipResult::Jumped:
            return PlaneStart::Jumped;
        case stream::SkipResult::NotTaken:
            return PlaneStart::NotTaken;
    }
    return PlaneStart::OneRay;
}

// The rays the lanes may leave to the one-ray walk: a zero or denormal component, or an origin
// in the world's closed box.
bool mayTakeOneRay(const VoxelWorld& w, const Ray& ray) {
    const Int3 size = w.size();
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
        if (!(std::abs(ray.direction[a]) > 0x1p-1024)) return true;
        inside = inside && ray.origin[a] >= 0.0 && ray.origin[a] <= size[a];
    }
    return inside;
}

struct Counts {
    long kinds[5] = {};
};

// startAtPlane on `rays` in runs of up to kMaxStartRays equals `reference` on each ray.
void expectSameStarts(const VoxelWorld& w, const std::vector<Ray>& rays, stream::Skip skip,
                      double tMax, Counts& counts) {
    for (std::size_t first = 0; first < rays.size(); first += stream::kMaxStartRays) {
        const std::span<const Ray> run =
            std::span(rays).subspan(first, std::min(stream::kMaxStartRays, rays.size() - first));
        shared::VoxelWalk walks[stream::kMaxStartRays];
        PlaneStart starts[stream::kMaxStartRays];
        stream::startAtPlane(w, run, skip, tMax, walks, starts);
        for (std::size_t j = 0; j < run.size(); ++j) {
            const Ray& ray = run[j];
            ++counts.kinds[static_cast<int>(starts[j])];
            // Only these rays may be left to the one-ray walk (an origin on the world's face
            // moving in starts from outside, in lanes).
            if (starts[j] == PlaneStart::OneRay) {
                EXPECT_TRUE(mayTakeOneRay(w, ray)) << "ray " << first + j;
                continue;
            }
            shared::VoxelWalk expected;
            const PlaneStart kind = reference(w, ray, skip, tMax, expected);
            ASSERT_EQ(static_cast<int>(starts[j]), static_cast<int>(kind)) << "ray " << first + j;
            if (kind != PlaneStart::Jumped && kind != PlaneStart::NotTaken) continue;
            const shared::VoxelWalk& mine = walks[j];
            EXPECT_TRUE(same(mine.t, expected.t)) << "ray " << first + j;
            EXPECT_EQ(mine.axis, expected.axis) << "ray " << first + j;
            for (int a = 0; a < 3; ++a) {
                EXPECT_EQ(mine.cell[a], expected.cell[a]) << "ray " << first + j << " axis " << a;
                EXPECT_EQ(mine.stp[a], expected.stp[a]) << "ray " << first + j << " axis " << a;
                EXPECT_TRUE(same(mine.next[a], expected.next[a]))
                    << "ray " << first + j << " axis " << a;
                EXPECT_TRUE(same(mine.inv[a], expected.inv[a])) << "ray " << first + j;
                EXPECT_TRUE(same(mine.o[a], expected.o[a]) && same(mine.d[a], expected.d[a]));
            }
            EXPECT_TRUE(mine.size.x == expected.size.x && mine.size.y == expected.size.y &&
                        mine.size.z == expected.size.z);
        }
    }
}

// Rays from outside: random ones aimed at points in and around the world, dyadic ones from
// origins on the planes of the world's faces, cells and bricks, and ones with zero, signed-zero
// and denormal components.
std::vector<Ray> outsideRays(const VoxelWorld& w) {
    const Int3 size = w.size();
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) {
        Vec3d o;
        do {
            for (int a = 0; a < 3; ++a) o[a] = -60.0 + unit(rng) * (size[a] + 120.0);
        } while (o.x >= 0 && o.y >= 0 && o.z >= 0 && o.x <= size.x && o.y <= size.y &&
                 o.z <= size.z);
        Vec3d target;
        for (int a = 0; a < 3; ++a) target[a] = -5.0 + unit(rng) * (size[a] + 10.0);
        rays.push_back({o, target - o});
    }
    // Origins on the planes of the world's faces (0 and the far face), cells and bricks, with
    // dyadic directions: exit t's tie exactly.
    const double faces[] = {-8.0, -4.0, -1.0, 0.0};
    for (const double f : faces) {
        for (int k = 0; k < 40; ++k) {
            // No zero component (those rays are left to the one-ray walk).
            const Vec3d d{0.25 * ((k % 8) - 3.5), -1.0, 0.125 * ((k / 8) - 2.5)};
            rays.push_back({{32.0 + k % 5, size.y - f, 16.0 + 0.5 * k}, d});
            rays.push_back({{f, 40.0 + 0.5 * (k % 8), 24.0 + k}, {1.0, d.x, d.z}});
            rays.push_back({{size.x - f, 48.0, 4.0 * (k % 30)}, {-1.0, d.z, d.x}});
            rays.push_back({{60.0 + k, 44.0, f}, {d.z, d.x, 1.0}});
        }
    }
    // Zero, signed-zero and denormal components; a ray along an edge of the world.
    const double smalls[] = {0.0, -0.0, 1e-320, -1e-320, 0x1p-1024, 1e-300};
    for (const double s : smalls) {
        rays.push_back({{40.5, 120.0, 30.25}, {s, -1.0, 0.25}});
        rays.push_back({{-10.0, 60.0, 20.0}, {1.0, s, -s}});
        rays.push_back({{-10.0, 0.0, 0.0}, {1.0, s, s}});
        rays.push_back({{75.0, 95.0, -3.0}, {0.1, -0.2, 1.0 + s}});
    }
    // Origins inside the world (the lanes leave them to the one-ray walk).
    rays.push_back({{75.0, 85.0, 60.0}, {0.3, -1.0, 0.2}});
    rays.push_back({{0.5, 85.0, 0.5}, {0.3, -1.0, 0.2}});
    return rays;
}

// The lanes' start on every target this CPU runs, for skips on each axis both ways, planes on
// chunk, brick and cell boundaries and at the world's faces, and tMax short of, at and past them.
TEST(VoxelTileStart, LanesMatchTheOneRayStartAndJumpOnEveryTarget) {
    const VoxelWorld w = world();
    const Int3 size = w.size();
    const std::vector<Ray> rays = outsideRays(w);
    std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        SCOPED_TRACE(hwy::TargetName(target));
        hwy::SetSupportedTargetsForTest(target);
        Counts counts;
        for (int m = 0; m < 3; ++m) {
            const int planes[] = {0, 1, 4, 21, 32, size[m] / 2, size[m] - 3, size[m]};
            for (const int plane : planes) {
                for (const double tMax : {kInfinity, 30.0, 80.0}) {
                    expectSameStarts(w, rays, {m, plane, false}, tMax, counts);
                }
            }
        }
        // Every kind seen: the comparison covers each path.
        for (int k = 0; k < 5; ++k) EXPECT_GT(counts.kinds[k], 1000) << "kind " << k;
    }
    hwy::SetSupportedTargetsForTest(0);
}

// A tile's bounds from its sub-tiles' (each read about the tile's main axis, then merged) are the
// tile's read whole, bit for bit, and give the same skip; on random cameras' rows and squares.
TEST(VoxelTileStart, SubTileBoundsMergeToTheTiles) {
    const VoxelWorld w = world();
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long tiles = 0, skips = 0;
    for (int i = 0; i < 30; ++i) {
        const Vec3d position{-100.0 + unit(rng) * 350.0, 95.0 + unit(rng) * 100.0,
                             -100.0 + unit(rng) * 330.0};
        const Vec3d target{unit(rng) * 150, unit(rng) * 90, unit(rng) * 134};
        const Camera camera =
            Camera::lookAt(position, target, 10.0 + unit(rng) * 80.0, 64, 24).value();
        std::vector<Ray> rays;
        for (int y = 0; y < camera.height(); ++y)
            for (int x = 0; x < camera.width(); ++x) rays.push_back(camera.primaryRay(x, y));
        for (std::size_t first = 0; first < rays.size(); first += kCameraTileRays) {
            const std::span<const Ray> tile = std::span(rays).subspan(first, kCameraTileRays);
            const stream::TileRays whole = stream::tileRays(tile);
            stream::TileRays merged = stream::tileRays(tile.first(16));
            for (std::size_t k = 16; k < tile.size(); k += 16) {
                merged = stream::mergeTileRays(
                    merged, stream::tileRays(tile.subspan(k, 16), merged.m, merged.sgn));
            }
            ASSERT_EQ(merged.ok, whole.ok);
            ++tiles;
            if (!whole.ok) continue;
            EXPECT_EQ(merged.m, whole.m);
            EXPECT_EQ(merged.sgn, whole.sgn);
            for (int a = 0; a < 3; ++a) {
                if (a == whole.m) continue;
                EXPECT_TRUE(same(merged.lo[a], whole.lo[a]) && same(merged.hi[a], whole.hi[a]));
                EXPECT_TRUE(same(merged.o[a], whole.o[a]));
            }
            const stream::Skip a = stream::tileSkip(w, merged), b = stream::tileSkip(w, tile);
            EXPECT_EQ(a.axis, b.axis);
            EXPECT_EQ(a.plane, b.plane);
            EXPECT_EQ(a.clear, b.clear);
            skips += b.axis >= 0 && !b.clear;
        }
    }
    EXPECT_GT(skips, 100);
    EXPECT_GT(tiles, 600);
    // A ray from another origin, or moving the other way along the main axis: no bounds.
    std::vector<Ray> odd(32, Ray{{10.0, 120.0, 10.0}, {0.1, -1.0, 0.2}});
    odd[20].origin.x += 1e-9;
    EXPECT_FALSE(stream::mergeTileRays(stream::tileRays(std::span(odd).first(16)),
                                       stream::tileRays(std::span(odd).subspan(16), 1, -1))
                     .ok);
    odd[20].origin.x -= 1e-9;
    odd[25].direction.y = 0.5;
    EXPECT_FALSE(stream::tileRays(std::span(odd).subspan(16), 1, -1).ok);
}

}  // namespace
}  // namespace luxel::voxel
