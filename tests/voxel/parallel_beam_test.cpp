// occludedBatch's beams of parallel rays (src/voxel/parallel_beam.cpp,
// docs/algorithms/voxel-traversal.md §4.7) against occluded(), ray by ray: shadow rays from the
// faces of terrain with floating blocks towards suns high and grazing, along the axes with signed
// zeros, at dyadic slopes from cell and brick planes (exact ties), from outside the world and from
// its faces, with tMax ending rays before and after the beam's plane, mixed with rays of other
// directions; and the beam's plane against the per-voxel walk: no ray of a beam meets a solid
// voxel past it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "luxel/voxel/dda.h"
#include "terrain_with_blocks.h"
#include "voxel/parallel_beam.h"

namespace luxel::voxel {
namespace {

// Terrain in the lower half with blocks floating over it; sides that are not multiples of the
// brick or the chunk.
VoxelWorld world() {
    return terrainWithBlocks({150, 90, 134}, 21, 120, 0.03, 50);
}

// occludedBatch equals occluded on every ray; returns how many are occluded.
int expectSameAsOccluded(const VoxelWorld& w, const std::vector<Ray>& rays, double tMax = kInfinity,
                         int stepCap = 0) {
    std::vector<std::uint8_t> blocked(rays.size(), 7);
    occludedBatch(w, rays, blocked, tMax, stepCap);
    int count = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const bool reference = occluded(w, rays[i], tMax, stepCap);
        EXPECT_EQ(blocked[i], reference ? 1 : 0) << "ray " << i;
        count += reference;
    }
    return count;
}

// Every beam occludedBatch would form from `rays`: no ray of it meets a solid voxel past its
// plane (the per-voxel walk, no jumps, as the judge: its hit's t is at most the plane's).
// Returns how many rays lie in beams.
int expectPlanesHold(const VoxelWorld& w, const std::vector<Ray>& rays) {
    int inBeams = 0;
    stream::BeamScan beams(w);
    for (std::size_t i = 0; i < rays.size();) {
        const std::span<const Ray> rest = std::span(rays).subspan(i);
        const std::size_t n = stream::beamLength(w, rest);
        if (n == 0) {
            ++i;
            continue;
        }
        const stream::BeamLimit limit = beams.limit(rest.first(n));
        EXPECT_GE(limit.axis, 0);
        for (std::size_t j = 0; j < n; ++j) {
            const Ray& ray = rest[j];
            EXPECT_EQ(ray.direction, rest[0].direction);
            const Hit hit = castRay(w, ray, kInfinity, 0, ChunkSkip::Disabled);
            if (hit.hit) {
                EXPECT_LE(hit.t, stream::beamPlaneT(ray, limit))
                    << "ray " << i + j << " plane " << limit.plane << " on axis " << limit.axis;
            }
        }
        inBeams += static_cast<int>(n);
        i += n;
    }
    return inBeams;
}

// Points on faces the sky sees (in the order the rays from above found them, neighbours after
// each other as in a picture's rows), each nudged off its face like a shading's shadow ray.
std::vector<Vec3d> surfacePoints(const VoxelWorld& w, int count, std::uint64_t seed, double nudge) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Vec3d> points;
    const Int3 size = w.size();
    // Rows of a grid of rays straight-ish down, so that consecutive points are neighbours.
    const int side = static_cast<int>(std::sqrt(static_cast<double>(count))) + 1;
    const Vec3d tilt = normalised({0.2 * (unit(rng) - 0.5), -1.0, 0.2 * (unit(rng) - 0.5)});
    for (int row = 0; row < side && static_cast<int>(points.size()) < count; ++row) {
        for (int col = 0; col < side && static_cast<int>(points.size()) < count; ++col) {
            const Vec3d origin{(col + 0.5 * unit(rng)) * size.x / side, size.y - 0.5,
                               (row + 0.5 * unit(rng)) * size.z / side};
            const Hit hit = castRay(w, {origin, tilt});
            if (!hit.hit) continue;
            const Vec3d n{static_cast<double>(hit.normal.x), static_cast<double>(hit.normal.y),
                          static_cast<double>(hit.normal.z)};
            points.push_back(hit.point + n * nudge);
        }
    }
    return points;
}

std::vector<Ray> shadowRays(const std::vector<Vec3d>& points, const Vec3d& sun) {
    std::vector<Ray> rays;
    for (const Vec3d& p : points) rays.push_back({p, sun});
    return rays;
}

TEST(VoxelParallelBeam, ShadowRaysMatchOccluded) {
    const VoxelWorld w = world();
    const std::vector<Vec3d> points = surfacePoints(w, 6000, 3, 1e-4);
    ASSERT_GT(points.size(), 4000u);
    int occludedRays = 0, rays = 0;
    for (const Vec3d& sun : {Vec3d{0.4, 1.0, 0.3}, Vec3d{-0.7, 0.5, 0.2}, Vec3d{0.1, 0.3, -0.9},
                             Vec3d{1.0, 0.05, 0.02}, Vec3d{-0.3, 0.2, 1.0}, Vec3d{0.0, 1.0, 0.0},
                             Vec3d{-0.0, 1.0, -0.0}, Vec3d{0.5, -1.0, 0.25}}) {
        const std::vector<Ray> shadow = shadowRays(points, normalised(sun));
        occludedRays += expectSameAsOccluded(w, shadow);
        EXPECT_GT(expectPlanesHold(w, shadow), static_cast<int>(shadow.size()) / 2);
        rays += static_cast<int>(shadow.size());
    }
    // Both answers occur often.
    EXPECT_GT(occludedRays, rays / 10);
    EXPECT_LT(occludedRays, rays - rays / 10);
}

TEST(VoxelParallelBeam, TMaxAndStepCap) {
    const VoxelWorld w = world();
    const std::vector<Ray> shadow =
        shadowRays(surfacePoints(w, 3000, 5, 1e-4), normalised({0.6, 0.7, -0.4}));
    for (double tMax : {0.0, 0.5, 2.0, 7.5, 30.0, 1e3}) expectSameAsOccluded(w, shadow, tMax);
    expectSameAsOccluded(w, shadow, -1.0);
    // Caps that end walks: the beams are not taken, the cap's result is occluded's.
    for (int cap : {1, 3, 10, 100}) expectSameAsOccluded(w, shadow, kInfinity, cap);
}

// Origins on cell and brick planes, dyadic directions (boundaries tie exactly at edges and
// corners), axis-parallel directions with signed zeros, origins on and outside the world's faces.
TEST(VoxelParallelBeam, TiesPlanesAndSignedZeros) {
    const VoxelWorld w = world();
    const Int3 size = w.size();
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> cell(0, 160);
    std::uniform_int_distribution<int> quarter(0, 3);
    const Vec3d directions[] = {{0.5, 1.0, 0.25},  {-0.5, -1.0, 0.25}, {1.0, 1.0, 1.0},
                                {-1.0, 0.5, -0.5}, {0.0, 1.0, 0.0},    {-0.0, -1.0, 0.0},
                                {0.0, 0.0, -1.0},  {1.0, -0.0, 0.0},   {0.25, 0.75, -0.5}};
    for (const Vec3d& d : directions) {
        std::vector<Ray> rays;
        for (int i = 0; i < 2000; ++i) {
            // Beams of neighbouring origins on planes: a random corner, then small dyadic offsets.
            const Vec3d corner{static_cast<double>(cell(rng) % size.x),
                               static_cast<double>(cell(rng) % size.y),
                               static_cast<double>(cell(rng) % size.z)};
            for (int k = 0; k < 16; ++k, ++i) {
                Vec3d o = corner;
                o.x += 0.25 * quarter(rng);
                o.y += 0.25 * quarter(rng) * (k % 2);
                o.z += quarter(rng);
                rays.push_back({o, d});
            }
        }
        // Origins on the world's faces and outside it.
        for (int k = 0; k < 64; ++k) {
            rays.push_back({{0.0, 0.5 * k, 3.0}, d});
            rays.push_back({{static_cast<double>(size.x), 0.5 * k, 3.0}, d});
            rays.push_back({{-2.0 - k, 40.0, 10.5}, d});
            rays.push_back({{20.25, static_cast<double>(size.y) + 0.5 * k, 10.5}, d});
        }
        expectSameAsOccluded(w, rays);
        expectSameAsOccluded(w, rays, 3.0);
        expectPlanesHold(w, rays);
    }
}

// Beams broken up by rays of other directions, non-finite rays and far origins: every ray still
// gets occluded's answer.
TEST(VoxelParallelBeam, MixedRuns) {
    const VoxelWorld w = world();
    const std::vector<Vec3d> points = surfacePoints(w, 3000, 9, 1e-4);
    const Vec3d sun = normalised({0.3, 1.0, -0.2});
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < points.size(); ++i) {
        rays.push_back({points[i], sun});
        if (i % 37 == 0) rays.push_back({points[i], normalised({unit(rng), 1.0, -unit(rng)})});
        if (i % 101 == 0) rays.push_back({points[i], {0.0, 0.0, 0.0}});
        if (i % 103 == 0) rays.push_back({{points[i].x, kInfinity, 0.0}, sun});
        if (i % 57 == 0) rays.push_back({points[i] + Vec3d{40.0, 0.0, 0.0}, sun});
        if (i % 211 == 0) rays.push_back({{1e7, -1e7, 3.0}, sun});
    }
    expectSameAsOccluded(w, rays);
    expectPlanesHold(w, rays);
}

// After an edit the brick reach is stale: occludedBatch takes occluded's own path, and after the
// refresh the beams again.
TEST(VoxelParallelBeam, EditsAndRefresh) {
    VoxelWorld w = world();
    const std::vector<Ray> shadow =
        shadowRays(surfacePoints(w, 2000, 13, 1e-4), normalised({0.4, 1.0, 0.3}));
    std::mt19937 rng(8);
    std::uniform_int_distribution<int> x(0, 149), y(40, 89), z(0, 133);
    for (int i = 0; i < 200; ++i) w.set(x(rng), y(rng), z(rng), Voxel{10, 20, 30, 255});
    expectSameAsOccluded(w, shadow);
    w.refreshEmptySpace();
    expectSameAsOccluded(w, shadow);
    expectPlanesHold(w, shadow);
}

}  // namespace
}  // namespace luxel::voxel
