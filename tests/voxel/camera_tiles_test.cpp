// castCameraRays (the tile frustum skip, docs/algorithms/voxel-traversal.md §4.6) against castRay,
// ray by ray and field by field (all but `steps`, which counts the skipping walk's own
// iterations): tiles of camera rays from above, grazing, from far away, from every side, straddling
// the world's edges, parallel to the axes with signed zeros, in row and square tile order, with
// tMax cutting rays short; cameras inside the world (first-person over the ground, in a cave and
// under overhangs, on cell, brick and chunk planes, near the world's faces, inside solid voxels);
// and the skip's frustum walk against a brute-force check of the cells the tile's rays visit
// before its plane, for tiles and for sub-tiles walked on from their tile's plane; clear tiles
// (no solid voxel in the frustum) against castRay, `steps` included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <random>
#include <span>
#include <vector>

#include "luxel/voxel/camera.h"
#include "luxel/voxel/dda.h"
#include "terrain_with_blocks.h"
#include "voxel/fast_walk.h"
#include "voxel/tile_frustum.h"
#include "voxel/walk_access.h"

namespace luxel::voxel {
namespace {

// Terrain in the lower half with blocks floating over it: empty space above, dense bricks below.
// Sides that are not multiples of the brick or the chunk.
VoxelWorld world() {
    return terrainWithBlocks({150, 90, 134}, 21, 80, 0.03, 50);
}

struct Totals {
    long rays = 0, hits = 0, skippedSteps = 0, castRaySteps = 0;
};

Totals add(Totals all, const Totals& t) {
    all.rays += t.rays;
    all.hits += t.hits;
    all.skippedSteps += t.skippedSteps;
    all.castRaySteps += t.castRaySteps;
    return all;
}

// castCameraRays on `rays` equals castRay on each, every field but `steps`.
Totals expectSameAsCastRay(const VoxelWorld& w, const std::vector<Ray>& rays,
                           double tMax = kInfinity, int stepCap = 0) {
    std::vector<Hit> hits(rays.size());
    castCameraRays(w, rays, hits, tMax, stepCap);
    Totals totals;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Hit reference = castRay(w, rays[i], tMax, stepCap);
        const Hit& mine = hits[i];
        EXPECT_EQ(mine.hit, reference.hit) << "ray " << i;
        EXPECT_EQ(mine.capped, reference.capped) << "ray " << i;
        EXPECT_EQ(mine.voxel, reference.voxel) << "ray " << i;
        EXPECT_EQ(mine.normal, reference.normal) << "ray " << i;
        // Bitwise: +inf on a miss on both sides, and the same double on a hit.
        EXPECT_EQ(std::memcmp(&mine.t, &reference.t, sizeof(double)), 0) << "ray " << i;
        EXPECT_EQ(mine.point, reference.point) << "ray " << i;
        EXPECT_EQ(mine.u, reference.u) << "ray " << i;
        EXPECT_EQ(mine.v, reference.v) << "ray " << i;
        ++totals.rays;
        totals.hits += reference.hit;
        totals.skippedSteps += mine.steps;
        totals.castRaySteps += reference.steps;
    }
    return totals;
}

// A camera's rays in image rows, or in 8x8 squares of pixels (tile after tile).
std::vector<Ray> cameraRays(const Camera& camera, bool squares) {
    std::vector<Ray> rays;
    const int w = camera.width(), h = camera.height();
    if (!squares) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) rays.push_back(camera.primaryRay(x, y));
        return rays;
    }
    for (int ty = 0; ty < h; ty += 8)
        for (int tx = 0; tx < w; tx += 8)
            for (int y = ty; y < std::min(ty + 8, h); ++y)
                for (int x = tx; x < std::min(tx + 8, w); ++x)
                    rays.push_back(camera.primaryRay(x, y));
    return rays;
}

// A tile of kCameraTileRays rays from `origin`, ray k along direction(k).
template <typename Direction>
void appendTile(std::vector<Ray>& rays, Vec3d origin, Direction&& direction) {
    for (std::size_t k = 0; k < kCameraTileRays; ++k)
        rays.push_back({origin, direction(static_cast<int>(k))});
}

// Hand-made tiles: castRay's results whole and with each of `tMaxes`; enough hits, and fewer
// steps than castRay's.
void expectHandMadeTiles(const VoxelWorld& w, const std::vector<Ray>& rays,
                         std::initializer_list<double> tMaxes) {
    const Totals t = expectSameAsCastRay(w, rays);
    EXPECT_GT(t.hits, static_cast<long>(rays.size()) / 3);
    EXPECT_LT(t.skippedSteps, t.castRaySteps);
    for (const double tMax : tMaxes) expectSameAsCastRay(w, rays, tMax);
}

Totals expectCamera(const VoxelWorld& w, const Camera& camera, double tMax = kInfinity) {
    Totals all;
    for (const bool squares : {false, true}) {
        all = add(all, expectSameAsCastRay(w, cameraRays(camera, squares), tMax));
    }
    return all;
}

TEST(VoxelCameraTiles, FromAboveLookingDownSkipsAndMatchesCastRay) {
    const VoxelWorld w = world();
    const Totals t =
        expectCamera(w, Camera::lookAt({75, 140, -30}, {75, 30, 90}, 60, 96, 64).value());
    EXPECT_GT(t.hits, t.rays / 3);
    // The skip took iterations off the walk (without it the two counts are equal).
    EXPECT_LT(t.skippedSteps, t.castRaySteps);
    // Straight down, the centre column parallel to y.
    expectCamera(w, Camera::create({75.5, 200, 67.5}, 0, -90, 50, 40, 40).value());
    expectCamera(w, Camera::create({20.25, 91, 30.75}, 30, -70, 80, 70, 33).value());
}

TEST(VoxelCameraTiles, GrazingFarAndFromEverySide) {
    const VoxelWorld w = world();
    // Grazing: just above the terrain's top, looking along it from outside.
    expectCamera(w, Camera::create({75, 62, -5}, 0, -1, 40, 80, 30).value());
    expectCamera(w, Camera::create({-3, 55, 60}, 90, 0, 60, 64, 48).value());
    // Far away (the world a few pixels wide in a corner of the image).
    expectCamera(w, Camera::lookAt({2e5, 7e4, -1.3e5}, {80, 40, 60}, 0.05, 48, 40).value());
    expectCamera(w, Camera::lookAt({-4000, 3000, 9000}, {75, 45, 67}, 2, 50, 50).value());
    // From every side, the world's edges and corners inside tiles (rays that miss next to rays
    // that hit), and from below.
    const Vec3d centre{75, 45, 67};
    const Vec3d from[] = {{300, 60, 67},  {-150, 100, 67}, {75, 45, 400},   {75, 80, -200},
                          {75, -120, 67}, {260, 200, 250}, {-90, -60, -80}, {150, 90, 134},
                          {75, 90, 67},   {0, 45, -0.0}};
    for (const Vec3d& p : from) {
        SCOPED_TRACE(testing::Message() << "camera at " << p.x << ", " << p.y << ", " << p.z);
        expectCamera(w, Camera::lookAt(p, centre + Vec3d{3.3, -2.1, 1.7}, 75, 72, 56).value());
    }
}

TEST(VoxelCameraTiles, TMaxEndsRaysBeforeAndAfterThePlane) {
    const VoxelWorld w = world();
    const Camera camera = Camera::lookAt({75, 140, -30}, {75, 30, 90}, 60, 64, 40).value();
    for (const double tMax : {0.0, 40.0, 95.0, 110.0, 130.0, 160.0}) {
        SCOPED_TRACE(testing::Message() << "tMax " << tMax);
        expectCamera(w, camera, tMax);
    }
    // A step cap below sx + sy + sz: castRayBatch, steps and capping included.
    const std::vector<Ray> rays = cameraRays(camera, true);
    std::vector<Hit> hits(rays.size());
    castCameraRays(w, rays, hits, kInfinity, 9);
    int capped = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Hit reference = castRay(w, rays[i], kInfinity, 9);
        ASSERT_EQ(hits[i].hit, reference.hit) << "ray " << i;
        EXPECT_EQ(hits[i].capped, reference.capped) << "ray " << i;
        EXPECT_EQ(hits[i].steps, reference.steps) << "ray " << i;
        EXPECT_EQ(hits[i].t, reference.t) << "ray " << i;
        capped += reference.capped;
    }
    EXPECT_GT(capped, 100);
}

// Hand-made tiles: directions parallel to the axes with signed zeros, exact dyadic slopes that put
// rays on brick and cell boundaries (ties at edges and corners inside the skipped slabs), origins
// on the world's faces and on brick planes, tiles with a ray that is not from the common origin.
TEST(VoxelCameraTiles, AxisParallelSignedZerosAndTies) {
    const VoxelWorld w = world();
    std::vector<Ray> rays;
    const auto tile = [&](Vec3d origin, auto&& direction) { appendTile(rays, origin, direction); };
    const double zeros[] = {0.0, -0.0};
    for (const double z0 : zeros) {
        for (const double z1 : zeros) {
            tile({40, 100, 40}, [&](int) { return Vec3d{z0, -1.0, z1}; });
            tile({40, 90, 40}, [&](int) { return Vec3d{z0, -2.0, z1}; });  // on the top face
            tile({40.5, 120, -0.0}, [&](int k) { return Vec3d{k % 2 ? z0 : 0.25, -1.0, z1}; });
            tile({-10, 60, 20}, [&](int k) { return Vec3d{1.0, z0, k % 3 ? z1 : -0.5}; });
            tile({160, 48, 134}, [&](int k) { return Vec3d{-1.0, (k % 4) * -0.125, z1}; });
        }
    }
    // Dyadic slopes from origins on brick and cell planes: boundary t's tie exactly.
    for (int k = 0; k < 8; ++k) {
        tile({32.0 + k, 96.0, 16.0 + 0.5 * k}, [&](int j) {
            return Vec3d{0.25 * ((j % 9) - 4), -1.0, 0.125 * ((j / 9) - 3)};
        });
        tile({-8.0, 64.0 + k, 24.0}, [&](int j) {
            return Vec3d{1.0, -0.25 * (j % 5), 0.5 * ((j / 5) % 5) - 1.0};
        });
    }
    // A tile with one ray from elsewhere (no skip for it), and a short last tile.
    tile({50, 130, 50}, [&](int j) { return Vec3d{0.01 * j, -1.0, 0.02}; });
    rays[rays.size() - 5].origin.x += 1e-9;
    for (int j = 0; j < 17; ++j) rays.push_back({{70, 110, 60}, {-0.03 * j, -1.0, 0.01 * j}});
    expectHandMadeTiles(w, rays, {10.0, 45.0, 50.0});
}

// 40 cameras at the positions `positionOf(rng, unit)` draws, each looking at a random point of the
// world with a random field of view, checked by expectCamera; a quarter of their rays or more hit,
// and the tiles save steps.
template <class Position>
void expectRandomCameras(std::uint64_t seed, Position&& positionOf) {
    const VoxelWorld w = world();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Totals all;
    for (int i = 0; i < 40; ++i) {
        const Vec3d position = positionOf(rng, unit);
        const Vec3d target{unit(rng) * 150, unit(rng) * 90, unit(rng) * 134};
        const double fov = 5.0 + unit(rng) * 100.0;
        all = add(all, expectCamera(w, Camera::lookAt(position, target, fov, 40, 30).value()));
    }
    EXPECT_GT(all.hits, all.rays / 4);
    EXPECT_LT(all.skippedSteps, all.castRaySteps);
}

// Many random cameras around the world, at random distances, looking at random points.
TEST(VoxelCameraTiles, RandomCameras) {
    expectRandomCameras(31, [](std::mt19937_64& rng, auto& unit) {
        Vec3d position;
        do {
            for (int a = 0; a < 3; ++a) position[a] = -200.0 + unit(rng) * 550.0;
        } while (position.x >= 0 && position.y >= 0 && position.z >= 0 && position.x < 150 &&
                 position.y < 90 && position.z < 134);
        return position;
    });
}

// Checks every tile of `rays` that gets a skip against the loop without jumps, which reports the
// first solid cell each ray enters: none lies before the tile's plane. Returns the tiles skipped.
int tilesStoppingBeforeTheirFirstSolidCell(const VoxelWorld& w, const std::vector<Ray>& rays) {
    int skipped = 0;
    for (std::size_t first = 0; first < rays.size(); first += kCameraTileRays) {
        const std::span<const Ray> tile(rays.data() + first, kCameraTileRays);
        const stream::Skip skip = stream::tileSkip(w, tile);
        if (skip.axis < 0) continue;
        ++skipped;
        for (const Ray& r : tile) {
            const Hit hit = castRay(w, r, kInfinity, 0, ChunkSkip::Disabled);
            if (!hit.hit) continue;
            const int c = hit.voxel[skip.axis];
            if (r.direction[skip.axis] > 0) {
                EXPECT_GE(c, skip.plane);
            } else {
                EXPECT_LT(c, skip.plane);
            }
        }
    }
    return skipped;
}

// The frustum walk alone: every cell that castRay's per-voxel loop (no jumps) visits before the
// tile's plane is empty, for tiles that got a plane.
TEST(VoxelCameraTiles, NoRayOfATileVisitsASolidCellBeforeItsPlane) {
    const VoxelWorld w = world();
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int planes = 0;
    for (int i = 0; i < 30; ++i) {
        const Vec3d position{-100 + unit(rng) * 350, 95 + unit(rng) * 100, -100 + unit(rng) * 330};
        const Vec3d target{unit(rng) * 150, unit(rng) * 60, unit(rng) * 134};
        const std::vector<Ray> rays =
            cameraRays(Camera::lookAt(position, target, 20 + unit(rng) * 60, 32, 16).value(), true);
        planes += tilesStoppingBeforeTheirFirstSolidCell(w, rays);
    }
    EXPECT_GT(planes, 100);
}

// Sub-tiles (§4.6 "Sub-tiles from outside"): the frustum walk of 16 rays of a tile begun at the
// tile's plane finds a plane at or past it before which none of its rays meets a solid cell (the
// loop without jumps as the judge), and calls the sub-tile clear only where none meets one at all.
TEST(VoxelCameraTiles, SubTilesFromTheTilesPlane) {
    const VoxelWorld w = world();
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int further = 0, clear = 0;
    for (int i = 0; i < 30; ++i) {
        const Vec3d position{-100 + unit(rng) * 350, 95 + unit(rng) * 100, -100 + unit(rng) * 330};
        const Vec3d target{unit(rng) * 150, unit(rng) * 90, unit(rng) * 134};
        const Camera camera = Camera::lookAt(position, target, 20 + unit(rng) * 60, 64, 24).value();
        for (const bool squares : {false, true}) {
            const std::vector<Ray> rays = cameraRays(camera, squares);
            for (std::size_t first = 0; first < rays.size(); first += kCameraTileRays) {
                const std::span<const Ray> tile(rays.data() + first, kCameraTileRays);
                const stream::Skip whole = stream::tileSkip(w, tile);
                if (whole.axis < 0 || whole.clear) continue;
                for (std::size_t sub = 0; sub < kCameraTileRays; sub += 16) {
                    const std::span<const Ray> part = tile.subspan(sub, 16);
                    const stream::Skip skip = stream::tileSkip(w, part, whole);
                    if (skip.axis != whole.axis) continue;
                    const int sgn = part.front().direction[skip.axis] > 0 ? 1 : -1;
                    EXPECT_GE(skip.plane * sgn, whole.plane * sgn);
                    further += skip.plane != whole.plane;
                    clear += skip.clear;
                    for (const Ray& r : part) {
                        const Hit hit = castRay(w, r, kInfinity, 0, ChunkSkip::Disabled);
                        if (skip.clear) {
                            EXPECT_FALSE(hit.hit);
                        }
                        if (!hit.hit) continue;
                        const int c = hit.voxel[skip.axis];
                        if (sgn > 0) {
                            EXPECT_GE(c, skip.plane);
                        } else {
                            EXPECT_LT(c, skip.plane);
                        }
                    }
                }
            }
            expectSameAsCastRay(w, rays);
        }
    }
    EXPECT_GT(further, 100);
    EXPECT_GT(clear, 10);
}

// The lowest empty y above column (x, z)'s highest solid voxel.
int groundY(const VoxelWorld& w, int x, int z) {
    for (int y = w.size().y - 1; y >= 0; --y)
        if (w.solid(x, y, z)) return y + 1;
    return 0;
}

// First-person cameras inside the world (§4.6 "From inside"): over the ground, grazing it, looking
// along the axes and up into the blocks, the ground's own brick below the camera.
TEST(VoxelCameraTiles, InsideTheWorldFirstPersonSkipsAndMatchesCastRay) {
    const VoxelWorld w = world();
    Totals all;
    const int spots[][2] = {{75, 67}, {20, 110}, {130, 15}, {3, 3}, {146, 130}};
    for (const auto& spot : spots) {
        const double ground = groundY(w, spot[0], spot[1]);
        for (const double above : {0.25, 2.5, 9.0}) {
            const Vec3d p{spot[0] + 0.37, ground + above, spot[1] + 0.61};
            if (p.y >= w.size().y) continue;
            for (const double yaw : {0.0, 90.0, 180.0, 270.0, 37.0}) {
                for (const double pitch : {0.0, -4.0, -30.0, 12.0}) {
                    SCOPED_TRACE(testing::Message() << "camera at " << p.x << ", " << p.y << ", "
                                                    << p.z << " yaw " << yaw << " pitch " << pitch);
                    all = add(all,
                              expectCamera(w, Camera::create(p, yaw, pitch, 70, 40, 24).value()));
                }
            }
        }
    }
    EXPECT_GT(all.hits, all.rays / 3);
    EXPECT_LT(all.skippedSteps, all.castRaySteps);
    // Grazing: a hair above the ground, looking along it, and tMax ending rays before and after
    // the plane.
    const double g = groundY(w, 75, 67);
    const Camera grazing = Camera::create({75.5, g + 1e-9, 67.5}, 10, -0.5, 50, 48, 32).value();
    for (const double tMax : {kInfinity, 0.0, 3.0, 20.0, 60.0}) expectCamera(w, grazing, tMax);
}

// A cave under the ground and a roof of stone over the camera (overhangs), cameras on cell, brick
// and chunk planes (integer, multiple of 4 and of 16 coordinates) looking along the axes (odd
// image sizes: the centre ray parallel to an axis), and cameras near and on the world's faces.
TEST(VoxelCameraTiles, InsideCavesOverhangsPlanesAndFaces) {
    VoxelWorld w = world();
    constexpr Voxel kStone{128, 128, 128, 255};
    for (int x = 30; x < 90; ++x)
        for (int y = 6; y < 19; ++y)
            for (int z = 40; z < 100; ++z) w.set(x, y, z, Voxel{});
    for (int x = 100; x < 140; ++x)
        for (int z = 20; z < 60; ++z) w.set(x, 84, z, kStone);
    w.refreshEmptySpace();
    Totals all;
    const Vec3d cameras[] = {{60.5, 12.5, 70.5},  {32.0, 8.0, 48.0},    {48.0, 16.0, 64.0},
                             {44.0, 12.0, 99.0},  {120.25, 83.0, 40.0}, {120.0, 80.0, 32.0},
                             {112.0, 64.0, 48.0}, {0.0, 70.0, 0.0},     {149.999, 88.5, 133.75},
                             {0.0, 89.0, 67.0},   {75.0, 60.0, 0.0},    {1e-300, 75.0, 133.0}};
    const double views[][2] = {{0, 0},   {90, 0}, {180, 0},   {270, 0}, {0, 90},
                               {0, -90}, {45, 0}, {200, -20}, {315, 25}};
    for (const Vec3d& p : cameras) {
        for (const auto& v : views) {
            SCOPED_TRACE(testing::Message() << "camera at " << p.x << ", " << p.y << ", " << p.z
                                            << " yaw " << v[0] << " pitch " << v[1]);
            all = add(all, expectCamera(w, Camera::create(p, v[0], v[1], 60, 33, 17).value()));
        }
    }
    EXPECT_GT(all.hits, all.rays / 3);
    EXPECT_LT(all.skippedSteps, all.castRaySteps);
}

// Hand-made tiles from inside: origins on cell and brick planes moving either way along axes with
// signed zeros, origins inside a solid voxel and in a brick that holds one (no skip), and rays
// that leave the world sideways before the plane.
TEST(VoxelCameraTiles, InsideHandMadeTiles) {
    const VoxelWorld w = world();
    std::vector<Ray> rays;
    const auto tile = [&](Vec3d origin, auto&& direction) { appendTile(rays, origin, direction); };
    const double zeros[] = {0.0, -0.0};
    for (const double z0 : zeros) {
        for (const double z1 : zeros) {
            tile({40, 80, 40}, [&](int) { return Vec3d{z0, -1.0, z1}; });
            tile({40, 80, 40}, [&](int) { return Vec3d{z0, 1.0, z1}; });
            tile({16, 64, 32}, [&](int k) { return Vec3d{-1.0, k % 2 ? z0 : -0.25, z1}; });
            tile({16, 64, 32}, [&](int k) { return Vec3d{1.0, k % 2 ? z0 : -0.25, z1}; });
            tile({0.0, 70, 60}, [&](int k) { return Vec3d{1.0, (k % 4) * -0.125, z1}; });
            tile({150 - 1e-12, 70, 60}, [&](int k) { return Vec3d{-1.0, (k % 4) * -0.125, z0}; });
        }
    }
    // Dyadic slopes from origins on brick and cell planes: boundary t's tie exactly.
    for (int k = 0; k < 8; ++k) {
        tile({32.0 + k, 80.0, 16.0 + 0.5 * k}, [&](int j) {
            return Vec3d{0.25 * ((j % 9) - 4), -1.0, 0.125 * ((j / 9) - 3)};
        });
        tile({4.0, 64.0 + k, 24.0}, [&](int j) {
            return Vec3d{1.0, -0.25 * (j % 5), 0.5 * ((j / 5) % 5) - 1.0};
        });
        tile({144.0, 60.0 + k, 128.0}, [&](int j) {
            return Vec3d{-0.5 * (j % 3), -0.25 * (j % 5), 1.0 + 0.125 * (j / 15)};
        });
    }
    // Inside a solid voxel, and just above the ground (its brick holds solid voxels).
    const double g = groundY(w, 70, 70);
    tile({70.5, g - 0.5, 70.5}, [&](int j) { return Vec3d{0.01 * j, -0.3, 1.0}; });
    tile({70.5, g + 0.5, 70.5}, [&](int j) { return Vec3d{0.01 * j, -0.1, 1.0}; });
    tile({70.5, g, 70.5}, [&](int j) { return Vec3d{1.0, -0.0, 0.02 * j - 0.6}; });
    expectHandMadeTiles(w, rays, {1.0, 10.0, 45.0});
}

// Random cameras anywhere inside the world (empty or solid cells), looking anywhere.
TEST(VoxelCameraTiles, RandomCamerasInside) {
    expectRandomCameras(47, [](std::mt19937_64& rng, auto& unit) {
        return Vec3d{unit(rng) * 150, unit(rng) * 90, unit(rng) * 134};
    });
}

// The frustum walk alone from inside: no ray of a tile meets a solid cell before its plane, and a
// tile whose origin lies in a solid voxel gets no plane.
TEST(VoxelCameraTiles, InsideNoRayOfATileVisitsASolidCellBeforeItsPlane) {
    const VoxelWorld w = world();
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int planes = 0, solidOrigins = 0;
    for (int i = 0; i < 60; ++i) {
        const Vec3d position{unit(rng) * 150, unit(rng) * 90, unit(rng) * 134};
        const Vec3d target{unit(rng) * 150, unit(rng) * 90, unit(rng) * 134};
        const std::vector<Ray> rays =
            cameraRays(Camera::lookAt(position, target, 20 + unit(rng) * 60, 32, 16).value(), true);
        const bool inSolid = w.solid(static_cast<int>(position.x), static_cast<int>(position.y),
                                     static_cast<int>(position.z));
        solidOrigins += inSolid;
        const int skipped = tilesStoppingBeforeTheirFirstSolidCell(w, rays);
        if (inSolid) {
            EXPECT_EQ(skipped, 0);  // an origin in a solid voxel gives no skip
        }
        planes += skipped;
    }
    EXPECT_GT(planes, 100);
    EXPECT_GT(solidOrigins, 0);
}

// Clear tiles (§4.6 "Clear tiles"): a tile whose frustum holds no solid voxel settles its rays as
// misses without walking them. Every field as castRay's, and `steps` what the walk would have
// counted: one jump out of the world for a ray that enters it, none for one that does not.
TEST(VoxelCameraTiles, ClearTilesMissAndCountOneJump) {
    const VoxelWorld w = world();
    std::vector<Camera> cameras = {
        // Above the blocks looking up and out, past the world's top edge and corners.
        Camera::lookAt({75, 95, -40}, {75, 200, 300}, 70, 96, 64).value(),
        Camera::lookAt({-60, 100, -60}, {75, 90, 67}, 60, 80, 60).value(),
        Camera::lookAt({300, 150, 250}, {150, 90, 134}, 40, 64, 64).value(),
        // Inside, over the blocks, looking up.
        Camera::create({75.5, 88.5, 67.5}, 10, 60, 90, 64, 48).value(),
        // Far away, the world's corner inside tiles.
        Camera::lookAt({2e5, 7e4, -1.3e5}, {150, 90, 134}, 0.05, 48, 40).value(),
    };
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 20; ++i) {
        const Vec3d position{-200.0 + unit(rng) * 550.0, 92.0 + unit(rng) * 200.0,
                             -200.0 + unit(rng) * 550.0};
        const Vec3d target{unit(rng) * 150, 60 + unit(rng) * 100, unit(rng) * 134};
        cameras.push_back(
            Camera::lookAt(position, target, 5.0 + unit(rng) * 100.0, 40, 32).value());
    }
    long clearRays = 0, entering = 0;
    for (const Camera& camera : cameras) {
        for (const bool squares : {false, true}) {
            const std::vector<Ray> rays = cameraRays(camera, squares);
            for (const double tMax : {kInfinity, 0.0, 30.0, 150.0}) {
                expectSameAsCastRay(w, rays, tMax);
                std::vector<Hit> hits(rays.size());
                castCameraRays(w, rays, hits, tMax, 0);
                for (std::size_t first = 0; first + kCameraTileRays <= rays.size();
                     first += kCameraTileRays) {
                    const std::span<const Ray> tile(rays.data() + first, kCameraTileRays);
                    if (!stream::tileSkip(w, tile).clear) continue;
                    for (std::size_t j = 0; j < kCameraTileRays; ++j) {
                        const Hit reference = castRay(w, tile[j], tMax);
                        ASSERT_FALSE(reference.hit);
                        EXPECT_EQ(hits[first + j].steps, reference.steps > 0 ? 1 : 0);
                        ++clearRays;
                        entering += reference.steps > 0;
                    }
                }
            }
        }
    }
    // Both kinds of clear rays: entering the world and passing it by (or ended by tMax).
    EXPECT_GT(entering, 1000);
    EXPECT_GT(clearRays - entering, 1000);
}

// The clip test of a clear tile's rays against castRay's start (steps > 0 exactly where the ray
// meets the world before tMax): rays on the world's faces, edges and corners, along them, with
// signed zeros, and random rays from around the world.
TEST(VoxelCameraTiles, EntersWorldIsCastRaysStart) {
    const VoxelWorld w = world();
    const Int3 size = w.size();
    std::vector<Ray> rays;
    const double faces[] = {-0.0, 0.0, 1e-300, 20.0, 89.99999999999999, 90.0, 150.0, 134.0, -1.0};
    const double dirs[] = {-0.0, 0.0, 1.0, -1.0, 0.5, -2.0, 1e-300, 3.0};
    for (const double ox : faces)
        for (const double oy : faces)
            for (const double oz : {-0.0, 0.0, 67.0, 134.0, -3.0})
                for (const double dx : dirs)
                    for (const double dy : dirs)
                        for (const double dz : {-1.0, 0.0, 1.0, -0.0, 0.25})
                            rays.push_back({{ox, oy, oz}, {dx, dy, dz}});
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const Vec3d o{75 + 200 * unit(rng), 45 + 150 * unit(rng), 67 + 200 * unit(rng)};
        // Aim at the world's edges and corners: targets on its box, a little off.
        Vec3d target{75 + 75 * std::round(unit(rng)), 45 + 45 * std::round(unit(rng)),
                     67 + 67 * std::round(unit(rng))};
        target[i % 3] += 1e-12 * unit(rng);
        rays.push_back({o, target - o});
    }
    long entering = 0;
    for (const Ray& ray : rays) {
        // A clear tile's rays: finite, eligible for the one-ray loop, moving (tileSkip).
        if (!finiteRay(ray) || !fast::eligible(w, ray)) continue;
        for (const double tMax : {kInfinity, 0.0, 100.0}) {
            const Hit reference = castRay(w, ray, tMax);
            ASSERT_EQ(fast::entersWorld(ray, size, tMax), reference.steps > 0)
                << ray.origin.x << " " << ray.origin.y << " " << ray.origin.z << " / "
                << ray.direction.x << " " << ray.direction.y << " " << ray.direction.z << " tMax "
                << tMax;
            entering += reference.steps > 0;
        }
    }
    EXPECT_GT(entering, 10000);
}

}  // namespace
}  // namespace luxel::voxel
