// Octree GPU structures shared by C++ and GLSL (offsets checked against the compiled shaders in
// tests/gpu/shared_layout_test.cpp).
//
// Buffers of octree_cast (a batch of rays; the CPU twin is octree::castRays, octree_trace.h):
//   0 nodes: the octree array, one uint per entry (include/luxel/octree/octree.h)
//   1 VoxelCastRay per ray (voxel_layout.h; `jumps` is unused)
//   2 VoxelCastHit per ray (voxel_layout.h; `entry` is the hit leaf's entry, `pad0` its colour
//     index: the entry, or its leaf order in a LeafOrder tree)
//   3 leafCounts: one uint per octant (LeafOrder trees), or one dummy
#ifndef LUXEL_GPU_SHARED_OCTREE_LAYOUT_H
#define LUXEL_GPU_SHARED_OCTREE_LAYOUT_H

#include "voxel_layout.h"

#ifdef __cplusplus
namespace luxel::gpu::shared {
#endif

#define LUXEL_OCTREE_CAST_GROUP 64

// What every octree pass needs to know about the tree and the batch.
struct OctreeCastPush {
    uint rays;
    uint stepCap;              // resolved: never 0
    uint depth;                // 1..16
    uint threshold;            // least opacity that stops a ray, 1..255
    uint sizeX, sizeY, sizeZ;  // the content box (Octree::extent)
    uint flags;                // LUXEL_OCTREE_LEAF_ORDER
};

// octree_render (one invocation per pixel; the CPU twin is octree::renderOctree,
// include/luxel/octree/octree_render.h) binds:
//   0 OctreeRenderParams
//   1 nodes (as octree_cast)
//   2 colours: one uint (r | g << 8 | b << 16 | a << 24) per entry or, in a LeafOrder tree, per
//     leaf; one dummy without colours
//   3 output: VoxelPixel per pixel (voxel_layout.h), rows top to bottom
//   4 leafCounts: as octree_cast's binding 3
//   5 lightCache: one float (T_sun) per corner of the light cache (shared/octree_light_cache.h),
//     or one dummy when lightStride is 0
#define LUXEL_OCTREE_RENDER_GROUP_X 8
#define LUXEL_OCTREE_RENDER_GROUP_Y 8

// octree_light_cache (one invocation per corner; the CPU twin is octree::fillLightCache,
// include/luxel/octree/octree_light_cache.h) binds 0 OctreeRenderParams, 1 nodes, 2 leafCounts
// (as octree_render) and 3 lightCache (written).
#define LUXEL_OCTREE_LIGHT_CACHE_GROUP 64

#define LUXEL_OCTREE_MODE_SURFACE 0u
#define LUXEL_OCTREE_MODE_VOLUME 1u
#define LUXEL_OCTREE_MODE_ADDITIVE 2u

#define LUXEL_OCTREE_SHADOWS 1u     // surface mode: shadow rays toward the sun
#define LUXEL_OCTREE_SCATTERING 2u  // volume mode: sunlight scattered in the medium
#define LUXEL_OCTREE_COLOURS 4u     // leaves have colours (binding 2)
#define LUXEL_OCTREE_LEAF_ORDER 8u  // colours in leaf order, indexed through the leaf counts

// Camera, light, medium and mode of a render; every member a 4-byte scalar (no std430 padding).
struct OctreeRenderParams {
    float originX, originY, originZ, sunRadius;  // camera; sun's angular radius (radians)
    float forwardX, forwardY, forwardZ, opacityScale;
    float rightX, rightY, rightZ, albedo;  // right * tan(fov / 2) * aspect; single-scatter albedo
    float upX, upY, upZ, phaseG;           // up * tan(fov / 2); Henyey-Greenstein g
    float sunX, sunY, sunZ, ambient;       // unit direction towards the sun; sky light fraction
    float sunR, sunG, sunB, octaveWeight;  // sun radiance scale (linear RGB); octave weight ratio
    float skyR, skyG, skyB;                // sky and background (linear RGB)
    uint lightStride;                      // light cache grid spacing in voxels; 0: none
    uint width, height, depth, mode;
    uint sizeX, sizeY, sizeZ, threshold;
    uint shadowSamples, flags, octaves, stepCap;
    uint windowLow, windowHigh, pad0, pad1;  // opacity transfer window (octreeAlpha)
};

#ifdef __cplusplus
static_assert(sizeof(OctreeCastPush) == 32);
static_assert(sizeof(OctreeRenderParams) == 176);
static_assert(offsetof(OctreeRenderParams, width) == 112);
}  // namespace luxel::gpu::shared
#endif

#endif
