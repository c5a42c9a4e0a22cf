// The sun-transmittance cache of the octree volume mode (docs/algorithms/sparse-voxel-octree.md
// §5, "Light cache"), shared by the CPU twin (octree::fillLightCache, octree_light_cache.h) and
// the GPU pass (octree/octree_light_cache.comp.glsl): T_sun traced exactly at the corners of a
// coarse grid over the content box, then read back at any point by trilinear interpolation.
// Corners hold the optical depth -ln T_sun, not T_sun: it grows linearly through a uniform
// medium, which trilinear interpolation reproduces exactly, where interpolating the exponential
// brightens every shadow; and a sample traces its first few voxels toward the sun exactly
// (octreeSunTransmittance, octree_render.h), where the medium just in front changes T_sun the
// most. Measured on tests/octree/octree_scattering_test.cpp's sphere at stride 1, relative L1 to
// the exact render: 0.13 interpolating T_sun, 0.045 the depth, 0.0006 with the near field.
//
// The grid: corners from the first voxel centre to the last, per axis ceil((size - 1) /
// lightStride) cells of equal length (at most lightStride voxels), so no corner sits on a voxel
// face where the traced ray would graze the walls; corner (i, j, k) is value
// i + (cells.x + 1) * (j + (cells.y + 1) * k). lightStride 0 means no cache.
//
// The per-corner value (octreeLightCacheCorner) is in octree_render.h, next to the transmittance
// it traces. The includer defines what octree_render.h needs and
//   float octreeLightCacheValue(LUXEL_OCTREE tree, uint corner): a corner's optical depth.
#ifndef LUXEL_GPU_SHARED_OCTREE_LIGHT_CACHE_H
#define LUXEL_GPU_SHARED_OCTREE_LIGHT_CACHE_H

#include "glsl_compat.h"
#include "octree_layout.h"

// The optical depth stored where the trace was cut off (T_sun below 1/512): T_sun = 3.4e-4,
// dark in 8 bits yet finite, so cells next to it interpolate smoothly.
#define LUXEL_OCTREE_LIGHT_CACHE_MAX_DEPTH 8.0f
// A sample traces the near field toward the sun exactly, this many strides but at least this
// many voxels, and reads the rest from the cache.
#define LUXEL_OCTREE_LIGHT_CACHE_NEAR_STRIDES 2.0f
#define LUXEL_OCTREE_LIGHT_CACHE_NEAR_VOXELS 8.0f

LUXEL_SHARED_BEGIN

// What a corner stores for the transmittance traced from it.
LUXEL_FUNC float octreeLightCacheDepth(float transmittance) {
    return transmittance > 0.0f ? min(-log(transmittance), LUXEL_OCTREE_LIGHT_CACHE_MAX_DEPTH)
                                : LUXEL_OCTREE_LIGHT_CACHE_MAX_DEPTH;
}

// Cells per axis (0 without a cache).
LUXEL_FUNC uvec3 octreeLightCacheCells(LUXEL_IN(OctreeRenderParams) p) {
    if (p.lightStride == 0u) return uvec3(0u);
    const uint s = p.lightStride;
    return uvec3(max((p.sizeX + s - 2u) / s, 1u), max((p.sizeY + s - 2u) / s, 1u),
                 max((p.sizeZ + s - 2u) / s, 1u));
}

LUXEL_FUNC uint octreeLightCacheCorners(LUXEL_IN(OctreeRenderParams) p) {
    const uvec3 c = octreeLightCacheCells(p);
    return (c.x + 1u) * (c.y + 1u) * (c.z + 1u);
}

// Where corner `corner` lies, in voxels (float on both backends, so both trace from one point).
LUXEL_FUNC vec3 octreeLightCacheCornerPoint(LUXEL_IN(OctreeRenderParams) p, uint corner) {
    const uvec3 c = octreeLightCacheCells(p);
    const uint i = corner % (c.x + 1u);
    const uint j = (corner / (c.x + 1u)) % (c.y + 1u);
    const uint k = corner / ((c.x + 1u) * (c.y + 1u));
    return vec3(0.5f + float(i) * float(p.sizeX - 1u) / float(c.x),
                0.5f + float(j) * float(p.sizeY - 1u) / float(c.y),
                0.5f + float(k) * float(p.sizeZ - 1u) / float(c.z));
}

LUXEL_FUNC uint octreeLightCacheIndex(uvec3 cells, uint i, uint j, uint k) {
    return i + (cells.x + 1u) * (j + (cells.y + 1u) * k);
}

// T_sun at `point`: the optical depth interpolated trilinearly between the 8 corners of its cell
// (points outside the box read the nearest cell, clamped to it).
LUXEL_FUNC float octreeLightCacheLookup(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p,
                                        vec3 point) {
    const uvec3 cells = octreeLightCacheCells(p);
    const vec3 u = vec3((point.x - 0.5f) * (float(cells.x) / float(max(p.sizeX - 1u, 1u))),
                        (point.y - 0.5f) * (float(cells.y) / float(max(p.sizeY - 1u, 1u))),
                        (point.z - 0.5f) * (float(cells.z) / float(max(p.sizeZ - 1u, 1u))));
    const uint i = uint(clamp(int(floor(u.x)), 0, int(cells.x) - 1));
    const uint j = uint(clamp(int(floor(u.y)), 0, int(cells.y) - 1));
    const uint k = uint(clamp(int(floor(u.z)), 0, int(cells.z) - 1));
    const float fx = clamp(u.x - float(i), 0.0f, 1.0f);
    const float fy = clamp(u.y - float(j), 0.0f, 1.0f);
    const float fz = clamp(u.z - float(k), 0.0f, 1.0f);
    const uint b = octreeLightCacheIndex(cells, i, j, k);
    const uint dy = cells.x + 1u;
    const uint dz = dy * (cells.y + 1u);
    const float c00 = mix(octreeLightCacheValue(tree, b), octreeLightCacheValue(tree, b + 1u), fx);
    const float c10 =
        mix(octreeLightCacheValue(tree, b + dy), octreeLightCacheValue(tree, b + dy + 1u), fx);
    const float c01 =
        mix(octreeLightCacheValue(tree, b + dz), octreeLightCacheValue(tree, b + dz + 1u), fx);
    const float c11 = mix(octreeLightCacheValue(tree, b + dz + dy),
                          octreeLightCacheValue(tree, b + dz + dy + 1u), fx);
    return exp(-mix(mix(c00, c10, fy), mix(c01, c11, fy), fz));
}

LUXEL_SHARED_END

#endif
