// Structures of the tile rendering passes (octree_tiles.h; docs/algorithms/sparse-voxel-octree.md
// §7), shared by C++ and GLSL and checked against the compiled shader in
// tests/gpu/octree_tiles_layout_test.cpp.
//
// octree_tiles (one dispatch per scale pass, one invocation per pixel; the CPU twin is
// octree::renderOctreeTiles, include/luxel/octree/octree_tiles.h) binds:
//   0 OctreeRenderParams (octree_layout.h)
//   1 nodes, 2 colours (as octree_render)
//   3 OctreeTileState per pixel: what the previous pass found, rewritten by this one
//   4 output: VoxelPixel per pixel (voxel_layout.h), written by the pass that shades
#ifndef LUXEL_GPU_SHARED_OCTREE_TILES_LAYOUT_H
#define LUXEL_GPU_SHARED_OCTREE_TILES_LAYOUT_H

#include "octree_layout.h"

#ifdef __cplusplus
namespace luxel::gpu::shared {
#endif

#define LUXEL_OCTREE_TILES_GROUP_X 8
#define LUXEL_OCTREE_TILES_GROUP_Y 8

// A pixel's state between passes.
#define LUXEL_OCTREE_TILE_MISS 0u      // no occupied cell on the ray (sky)
#define LUXEL_OCTREE_TILE_FOUND 1u     // `cell` (at the last pass's level) is occupied
#define LUXEL_OCTREE_TILE_DEAD_END 2u  // a coarser pass found a cell; no finer sample inside hit

struct OctreeTileState {
    uint status;
    int cellX, cellY, cellZ;  // in cells of 2^level voxels
    uint level;
    uint entry;    // the octree entry the point query stopped at (a leaf's gives the colour)
    uint samples;  // point queries so far, all passes
    uint pass;     // passes run so far
};

// Which scale a pass works at: tiles of 2^(parentLevel - level) cells a side.
struct OctreeTilesPush {
    uint pass;
    uint level;        // cells of 2^level voxels
    uint parentLevel;  // the cell the previous pass found is 2^parentLevel wide (depth: the cube)
    uint shade;        // 1: write the image from the state after this pass
};

#ifdef __cplusplus
static_assert(sizeof(OctreeTileState) == 32);
static_assert(sizeof(OctreeTilesPush) == 16);
}  // namespace luxel::gpu::shared
#endif

#endif
