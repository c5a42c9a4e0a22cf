// The WebGL octree design's rendering proposal (docs/algorithms/sparse-voxel-octree.md §7): fixed
// tiles of 8^3 cells, one scale per pass, coarse to fine, and a fixed-step march in each pass
// instead of the exact traversal. renderOctreeTiles is the CPU twin of OctreeTilesGpu::render
// (octree_tiles_gpu.h); compareWithExact measures what the method loses against castRay
// (octree_trace.h), the traversal of the surface mode of renderOctree (octree_render.h).
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/core/vec.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/voxel/camera.h"

namespace luxel::octree {

struct TileOptions {
    // Tiles are 2^tileBits cells a side: pass k works on cells 2^(tileBits * (passes - 1 - k))
    // voxels wide. 3 is the design's 8^3 (4 passes for 4096^3); tileBits >= depth is one pass
    // of a plain fixed-step march over voxels.
    int tileBits = 3;
    // How many passes to run (0: all). Fewer is a frame of the design's temporal accumulation,
    // which adds one finer pass per frame: the image shows the cells found so far.
    int passes = 0;
};

Status validateTileOptions(const TileOptions& options);

// The number of scale passes and the level (cells of 2^level voxels) of pass `pass`.
int tilePassCount(int depth, int tileBits);
int tilePassLevel(int depth, int tileBits, int pass);

// What a pixel's ray found.
struct TilePixel {
    bool hit = false;
    bool deadEnd = false;  // a coarser pass found a cell but no finer sample inside it was solid
    Int3 cell;             // the hit cell, in cells of 2^level voxels (voxels after all passes)
    int level = 0;
    std::uint32_t entry = 0;  // the octree entry found for it (0 on a miss)
    int samples = 0;          // point queries over all passes
};

struct TileRender {
    Image image;                    // linear RGB, the camera's size
    std::vector<TilePixel> pixels;  // rows top to bottom
};

// Surface shading only (options.mode is ignored); `tree` must be valid.
Result<TileRender> renderOctreeTiles(const Octree& tree, const voxel::Camera& camera,
                                     const OctreeRenderOptions& options,
                                     const TileOptions& tiles = {});

// The exact traversal's hit of every pixel (the same rays, castRay's walk and threshold), as
// TilePixels at level 0: what compareWithExact compares with.
std::vector<TilePixel> exactPixels(const Octree& tree, const voxel::Camera& camera,
                                   const OctreeRenderOptions& options);

// Pixel counts: every pixel is exactly one of sameVoxel, differentVoxel, missedSurface,
// falseHit, or a miss of both.
struct TileComparison {
    std::int64_t pixels = 0;
    std::int64_t exactHits = 0;
    std::int64_t tileHits = 0;
    std::int64_t sameVoxel = 0;       // both hit the same voxel
    std::int64_t differentVoxel = 0;  // both hit, different voxels
    std::int64_t missedSurface = 0;   // the exact traversal hits, the tiles miss
    std::int64_t falseHit = 0;        // the tiles hit, the exact traversal misses
    std::int64_t deadEnds = 0;        // of missedSurface: a coarse cell was found, then nothing
    std::int64_t samples = 0;         // point queries of the tile render, all pixels

    // Pixels whose hit voxel is not the exact one (differentVoxel + missedSurface + falseHit).
    double differingPercent() const;
    double missedPercent() const;
};

// `tiles` are a render's pixels at level 0 (all passes); `exact` from exactPixels.
Result<TileComparison> compareTiles(const std::vector<TilePixel>& tiles,
                                    const std::vector<TilePixel>& exact);

}  // namespace luxel::octree
