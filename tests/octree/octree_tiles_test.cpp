// The WebGL octree design's tile rendering (octree_tiles.h) against the exact traversal: where its
// claim holds (an opaque floor on the coarse grid), where it loses pixels (a floor off that grid,
// one-voxel walls at grazing angles, a one-voxel rod seen corner-on), the counting itself, the
// frames of temporal accumulation, and the GPU pass against its CPU twin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "luxel/gpu/context.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_gpu.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/octree_tiles.h"
#include "luxel/octree/octree_tiles_gpu.h"
#include "luxel/octree/volume_generators.h"
#include "support/gpu_test_context.h"

namespace luxel::octree {
namespace {

OctreeRenderOptions noShadows() {
    OctreeRenderOptions o;
    o.shadows = false;
    return o;
}

// An opaque floor y < top in a 64^3 tree (two passes of 8^3 tiles: cells of 8, then voxels),
// each voxel its own colour so a shifted hit shows.
Octree floorTree(int top, AttributeLayout layout = AttributeLayout::PerEntry) {
    Volume v = *Volume::create({64, 64, 64}, true);
    for (int z = 0; z < 64; ++z)
        for (int y = 0; y < top; ++y)
            for (int x = 0; x < 64; ++x)
                v.set(x, y, z, 255,
                      Colour{static_cast<std::uint8_t>(x * 4), static_cast<std::uint8_t>(y * 4),
                             static_cast<std::uint8_t>(z * 4), 1});
    return *buildOctree(v, {.layout = layout});
}

TileComparison compare(const Octree& tree, const voxel::Camera& camera,
                       const TileOptions& tiles = {}) {
    auto render = renderOctreeTiles(tree, camera, noShadows(), tiles);
    EXPECT_TRUE(render.ok()) << render.error().message();
    auto c = compareTiles(render->pixels, exactPixels(tree, camera, noShadows()));
    EXPECT_TRUE(c.ok());
    std::printf(
        "  %lld pixels: exact hits %lld, same voxel %lld, different %lld, missed %lld (dead ends "
        "%lld), false hits %lld: %.2f%% differ, %.2f%% missed\n",
        static_cast<long long>(c->pixels), static_cast<long long>(c->exactHits),
        static_cast<long long>(c->sameVoxel), static_cast<long long>(c->differentVoxel),
        static_cast<long long>(c->missedSurface), static_cast<long long>(c->deadEnds),
        static_cast<long long>(c->falseHit), c->differingPercent(), c->missedPercent());
    return *c;
}

// Seen from above every ray's dominant axis is y: each sample is where the ray enters a y slab,
// which on a floor whose top lies on the coarse cells' grid is the voxel the exact walk enters.
TEST(OctreeTiles, OpaqueFloorOnTheCoarseGridFromAboveLosesNothing) {
    const Octree tree = floorTree(16);
    const auto camera = *voxel::Camera::lookAt({30.3, 58.7, 27.9}, {33.1, 0.0, 35.2}, 40, 64, 64);
    const TileComparison c = compare(tree, camera);
    EXPECT_EQ(c.exactHits, c.pixels);
    EXPECT_EQ(c.sameVoxel, c.pixels);
}

// Colours in leaf order (the geometry DAG shared regardless of colour) reach the tile passes too:
// where every pixel hits the exact voxel, the picture is the surface mode's, pixel for pixel.
TEST(OctreeTiles, LeafOrderColoursShadeAsTheSurfaceMode) {
    const Octree tree = floorTree(16, AttributeLayout::LeafOrder);
    ASSERT_TRUE(tree.leafOrder());
    const auto camera = *voxel::Camera::lookAt({30.3, 58.7, 27.9}, {33.1, 0.0, 35.2}, 40, 64, 64);
    auto tiles = renderOctreeTiles(tree, camera, noShadows(), {});
    auto exact = renderOctree(tree, camera, noShadows());
    ASSERT_TRUE(tiles.ok() && exact.ok());
    double diff = 0, sum = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                diff += std::abs(tiles->image.at(x, y, ch) - exact->at(x, y, ch));
                sum += std::abs(exact->at(x, y, ch));
            }
    EXPECT_LT(diff / sum, 1e-5) << "relative L1 " << diff / sum;
}

// "tiles" is a render mode: renderOctree and OctreeGpu::render give the tile passes' picture.
TEST(OctreeTiles, IsARenderModeOnBothBackends) {
    ASSERT_EQ(*parseOctreeMode("tiles"), OctreeMode::Tiles);
    EXPECT_STREQ(octreeModeName(OctreeMode::Tiles), "tiles");
    const Octree tree = floorTree(13);
    const auto camera = *voxel::Camera::lookAt({30.3, 58.7, 27.9}, {33.1, 0.0, 35.2}, 40, 48, 48);
    OctreeRenderOptions o = noShadows();
    o.mode = OctreeMode::Tiles;
    auto viaMode = renderOctree(tree, camera, o);
    auto direct = renderOctreeTiles(tree, camera, noShadows(), {});
    ASSERT_TRUE(viaMode.ok() && direct.ok());
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) ASSERT_EQ(viaMode->at(x, y, 1), direct->image.at(x, y, 1));
    if (!test::sharedGpuContext()) GTEST_SKIP() << "no Vulkan device for the GPU half";
    auto uploaded = OctreeGpu::create(*test::sharedGpuContext(), tree);
    ASSERT_TRUE(uploaded.ok()) << uploaded.error().message();
    auto gpu = uploaded->render(camera, o);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    double diff = 0, sum = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                diff += std::abs(gpu->at(x, y, ch) - viaMode->at(x, y, ch));
                sum += std::abs(viaMode->at(x, y, ch));
            }
    EXPECT_LT(diff / sum, 1e-2) << "relative L1 " << diff / sum;
    // The surface mode on the same upload still renders the exact walk.
    o.mode = OctreeMode::Surface;
    EXPECT_TRUE(uploaded->render(camera, o).ok());
}

// The same floor three voxels lower: the coarse cell a ray is found in holds the floor's top, but
// a ray that leaves that cell through a side before reaching the top has no finer sample inside
// it (a dead end), and the pixel shows sky where the exact walk hits the floor in the next cell.
// Every other pixel still hits the exact voxel.
TEST(OctreeTiles, OpaqueFloorOffTheCoarseGridLosesPixelsAtDeadEnds) {
    const Octree tree = floorTree(13);
    const auto camera = *voxel::Camera::lookAt({30.3, 58.7, 27.9}, {33.1, 0.0, 35.2}, 40, 64, 64);
    const TileComparison c = compare(tree, camera);
    EXPECT_EQ(c.exactHits, c.pixels);
    EXPECT_EQ(c.differentVoxel, 0);
    EXPECT_EQ(c.falseHit, 0);
    EXPECT_GT(c.missedSurface, 0);
    EXPECT_EQ(c.deadEnds, c.missedSurface);
    EXPECT_EQ(c.sameVoxel + c.missedSurface, c.pixels);
}

// At a shallow angle the dominant axis is z: a ray entering the floor's top inside a z slab is
// sampled only where it enters the next coarse slab, so its hit moves up to one coarse cell (8
// voxels) along the ray; and a ray entering the top in the last slab before the end of the floor
// (the content box's face z = 64) has no later sample at all: a corner clipped at the coarse
// scale. Nothing else is lost and nothing invented.
TEST(OctreeTiles, OpaqueFloorAtAShallowAngleShiftsHitsByAtMostACoarseCell) {
    const Octree tree = floorTree(16);
    const auto camera = *voxel::Camera::lookAt({32.4, 24.3, 0.6}, {32.4, 10.0, 63.0}, 40, 64, 48);
    auto render = renderOctreeTiles(tree, camera, noShadows());
    ASSERT_TRUE(render.ok());
    const std::vector<TilePixel> exact = exactPixels(tree, camera, noShadows());
    const TileComparison c = compare(tree, camera);
    EXPECT_GT(c.exactHits, c.pixels / 2);
    EXPECT_EQ(c.falseHit, 0);
    EXPECT_EQ(c.deadEnds, 0);
    EXPECT_GT(c.differentVoxel, c.exactHits / 2);
    int shift = 0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
        const TilePixel& t = render->pixels[i];
        const TilePixel& e = exact[i];
        if (e.hit && !t.hit) {
            EXPECT_GE(e.cell.z, 56) << "pixel " << i;  // the floor's last coarse slab
        }
        if (e.hit && t.hit) {
            shift = std::max({shift, std::abs(t.cell.x - e.cell.x), std::abs(t.cell.y - e.cell.y),
                              std::abs(t.cell.z - e.cell.z)});
        }
    }
    std::printf("  largest shift of a hit voxel: %d voxels\n", shift);
    EXPECT_LE(shift, 8);
}

// Two one-voxel walls x = 20 and x = 44 (full height and depth), seen from between them along z.
Octree wallsTree() {
    Volume v = *Volume::create({64, 64, 64});
    for (int z = 0; z < 64; ++z)
        for (int y = 0; y < 64; ++y) {
            v.set(20, y, z, 255);
            v.set(44, y, z, 255);
        }
    return *buildOctree(v);
}

// A wall one voxel thick is never skipped by one sample per dominant slab (the ray's chord in it
// is longer than a slab), so a single pass over voxels (tile bits >= depth) finds every wall
// pixel but where the volume ends; with 8^3 tiles the coarse pass finds the wall's coarse cell
// while the ray is still in front of the wall, and rays that leave that cell before reaching it
// dead-end.
TEST(OctreeTiles, ThinWallsAtGrazingAnglesAreLostByTheHierarchyNotTheMarch) {
    const Octree tree = wallsTree();
    const auto camera = *voxel::Camera::lookAt({32.3, 30.7, 1.1}, {32.3, 28.0, 64.0}, 40, 64, 48);
    const TileComparison march = compare(tree, camera, {.tileBits = 6});
    EXPECT_GT(march.exactHits, march.pixels / 2);
    EXPECT_EQ(march.falseHit, 0);
    // Only rays reaching a wall in the last slab before the box's end (z = 64) are missed.
    auto single = renderOctreeTiles(tree, camera, noShadows(), {.tileBits = 6});
    ASSERT_TRUE(single.ok());
    const std::vector<TilePixel> exact = exactPixels(tree, camera, noShadows());
    int atTheEnd = 0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
        if (exact[i].hit && !single->pixels[i].hit) {
            EXPECT_EQ(exact[i].cell.z, 63) << "pixel " << i;
            ++atTheEnd;
        }
    }
    EXPECT_EQ(march.missedSurface, atTheEnd);
    EXPECT_LT(march.missedSurface, march.pixels / 100);
    const TileComparison tiles = compare(tree, camera);
    EXPECT_EQ(tiles.exactHits, march.exactHits);
    EXPECT_GT(tiles.missedSurface, tiles.pixels / 50);
    EXPECT_EQ(tiles.deadEnds, tiles.missedSurface);
    EXPECT_EQ(tiles.falseHit, 0);
}

// A one-voxel rod along y at (x, z) = (16, 16), seen with z dominant: one pass over voxels samples
// the rod's column only where a ray enters the slab z = 16, so exactly the rays that cross the
// rod but are outside x in [16, 17) at z = 16 (they clip the rod through its x face) must be
// counted as missed. Rays within `eps` of an edge are left undecided (float vs double rays).
TEST(OctreeTiles, CountsTheRaysThatClipAThinRodCornerOn) {
    Volume v = *Volume::create({32, 32, 32});
    for (int y = 0; y < 32; ++y) v.set(16, y, 16, 255);
    const Octree tree = *buildOctree(v);
    const auto camera =
        *voxel::Camera::lookAt({13.37, 16.21, 1.13}, {16.6, 16.21, 16.4}, 30, 96, 64);
    auto render = renderOctreeTiles(tree, camera, noShadows(), {.tileBits = 5});
    ASSERT_TRUE(render.ok());
    const std::vector<TilePixel> exact = exactPixels(tree, camera, noShadows());
    auto c = compareTiles(render->pixels, exact);
    ASSERT_TRUE(c.ok());
    const double eps = 1e-4;
    int clear = 0, undecided = 0, crossing = 0;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const voxel::Ray r = camera.primaryRay(x, y);
            ASSERT_GT(r.direction.z, std::abs(r.direction.x));
            const double x16 = r.origin.x + (16.0 - r.origin.z) / r.direction.z * r.direction.x;
            const double x17 = r.origin.x + (17.0 - r.origin.z) / r.direction.z * r.direction.x;
            const double lo = std::min(x16, x17), hi = std::max(x16, x17);
            if (hi < 16.0 - eps || lo > 17.0 + eps) continue;  // misses the column
            if (hi < 16.0 + eps || lo > 17.0 - eps) {
                ++undecided;  // grazes an edge
                continue;
            }
            ++crossing;
            if (x16 < 16.0 - eps || x16 > 17.0 + eps) ++clear;
            if (std::abs(x16 - 16.0) <= eps || std::abs(x16 - 17.0) <= eps) ++undecided;
        }
    }
    std::printf(
        "  rod: %d rays cross it, %d clip it through its side, %d undecided; counted %lld\n",
        crossing, clear, undecided, static_cast<long long>(c->missedSurface));
    EXPECT_GT(clear, 20);
    EXPECT_GE(c->missedSurface, clear);
    EXPECT_LE(c->missedSurface, clear + undecided);
    EXPECT_EQ(c->sameVoxel + c->missedSurface, c->exactHits);
}

// compareTiles on hand-made differences: each kind counted once per pixel.
TEST(OctreeTiles, ComparisonCountsEachKindOfDifference) {
    std::vector<TilePixel> exact(100), tiles(100);
    for (int i = 0; i < 60; ++i) {
        exact[i].hit = true;
        exact[i].cell = {i, 1, 2};
    }
    tiles = exact;
    for (int i = 0; i < 7; ++i) {
        tiles[i] = TilePixel{};
        tiles[i].deadEnd = i < 3;
    }                                                    // 7 missed, 3 dead ends
    for (int i = 10; i < 15; ++i) tiles[i].cell.y += 1;  // 5 different voxels
    for (int i = 70; i < 73; ++i) tiles[i].hit = true;   // 3 false hits
    auto c = compareTiles(tiles, exact);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->exactHits, 60);
    EXPECT_EQ(c->tileHits, 56);
    EXPECT_EQ(c->sameVoxel, 48);
    EXPECT_EQ(c->differentVoxel, 5);
    EXPECT_EQ(c->missedSurface, 7);
    EXPECT_EQ(c->deadEnds, 3);
    EXPECT_EQ(c->falseHit, 3);
    EXPECT_DOUBLE_EQ(c->differingPercent(), 15.0);
    EXPECT_DOUBLE_EQ(c->missedPercent(), 7.0);
    EXPECT_FALSE(compareTiles(tiles, std::vector<TilePixel>(99)).ok());
}

// Temporal accumulation: after the first pass (frame 1) a pixel shows the coarse cell that holds
// its final voxel; every later pass refines inside it.
TEST(OctreeTiles, EachFrameRefinesInsideTheCellOfTheFrameBefore) {
    const Octree tree = *buildOctree(*makePhantom(64));
    const auto camera = *voxel::Camera::lookAt({120, 80, -60}, {32, 32, 32}, 40, 48, 36);
    auto first = renderOctreeTiles(tree, camera, noShadows(), {.passes = 1});
    auto last = renderOctreeTiles(tree, camera, noShadows());
    ASSERT_TRUE(first.ok() && last.ok());
    const int level = tilePassLevel(tree.depth, 3, 0);
    EXPECT_EQ(level, 3);
    int hits = 0;
    for (std::size_t i = 0; i < last->pixels.size(); ++i) {
        const TilePixel& f = first->pixels[i];
        const TilePixel& l = last->pixels[i];
        if (f.hit) {
            EXPECT_EQ(f.level, level);
        }
        if (!l.hit) continue;
        ++hits;
        ASSERT_TRUE(f.hit) << "pixel " << i;
        EXPECT_EQ(f.cell, (Int3{l.cell.x >> level, l.cell.y >> level, l.cell.z >> level}));
    }
    EXPECT_GT(hits, 150);
}

TEST(OctreeTiles, RefusesBadTileOptions) {
    const Octree tree = floorTree(16);
    const auto camera = *voxel::Camera::lookAt({30, 50, 20}, {32, 0, 32}, 40, 8, 8);
    auto bad = renderOctreeTiles(tree, camera, {}, {.tileBits = 0});
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("tile bits"), std::string::npos);
    EXPECT_FALSE(renderOctreeTiles(tree, camera, {}, {.passes = -1}).ok());
    EXPECT_EQ(tilePassCount(12, 3), 4);  // the design's 4 passes of 8^3 tiles for 4096^3
    EXPECT_EQ(tilePassCount(7, 3), 3);
    EXPECT_EQ(tilePassLevel(7, 3, 0), 6);  // the first tile is 2 cells a side
}

// Float (GPU) against double (CPU): the same passes, so hit cells agree but for rays within
// rounding of a cell edge; shading agrees on the pixels that hit alike.
TEST(OctreeTiles, GpuPassesMatchTheCpuTwin) {
    if (!test::sharedGpuContext())
        GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    struct Case {
        Octree tree;
        voxel::Camera camera;
    };
    const Case cases[] = {
        {*buildOctree(*makePhantom(48)),
         *voxel::Camera::lookAt({90, 60, -50}, {24, 24, 24}, 40, 64, 48)},
        {floorTree(13), *voxel::Camera::lookAt({30.3, 58.7, 27.9}, {33.1, 0.0, 35.2}, 40, 48, 48)},
        {floorTree(16, AttributeLayout::LeafOrder),
         *voxel::Camera::lookAt({30.3, 58.7, 27.9}, {33.1, 0.0, 35.2}, 40, 48, 48)},
        {wallsTree(), *voxel::Camera::lookAt({32.3, 30.7, 1.1}, {32.3, 28.0, 64.0}, 40, 64, 48)},
    };
    for (const Case& c : cases) {
        auto uploaded = OctreeTilesGpu::create(*test::sharedGpuContext(), c.tree);
        ASSERT_TRUE(uploaded.ok()) << uploaded.error().message();
        const OctreeRenderOptions options;  // with sun shadows
        for (int passes : {1, 0}) {
            std::vector<gpu::PassTiming> timings;
            auto gpu = uploaded->render(c.camera, options, {.passes = passes}, &timings);
            auto cpu = renderOctreeTiles(c.tree, c.camera, options, {.passes = passes});
            ASSERT_TRUE(gpu.ok() && cpu.ok()) << (gpu.ok() ? "" : gpu.error().message());
            EXPECT_EQ(static_cast<int>(timings.size()),
                      passes == 1 ? 1 : tilePassCount(c.tree.depth, 3));
            int differ = 0;
            double colourDiff = 0, colourSum = 0;
            for (std::size_t i = 0; i < cpu->pixels.size(); ++i) {
                const TilePixel& a = cpu->pixels[i];
                const TilePixel& b = gpu->pixels[i];
                if (a.hit != b.hit || a.cell != b.cell || a.level != b.level) {
                    ++differ;
                    continue;
                }
                const int x = static_cast<int>(i) % c.camera.width();
                const int y = static_cast<int>(i) / c.camera.width();
                for (int ch = 0; ch < 3; ++ch) {
                    colourDiff += std::abs(gpu->image.at(x, y, ch) - cpu->image.at(x, y, ch));
                    colourSum += std::abs(cpu->image.at(x, y, ch));
                }
            }
            const int pixels = static_cast<int>(cpu->pixels.size());
            EXPECT_LE(differ, pixels / 200) << "passes " << passes;
            EXPECT_LT(colourDiff / colourSum, 5e-3) << "passes " << passes;
        }
    }
    EXPECT_EQ(test::sharedGpuContext()->validationMessages(), 0)
        << test::sharedGpuContext()->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::octree
