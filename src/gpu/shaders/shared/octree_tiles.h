// The WebGL octree design's rendering proposal (docs/algorithms/sparse-voxel-octree.md §7),
// shared by the CPU twin (octree::renderOctreeTiles) and the GPU pass
// (octree/octree_tiles.comp.glsl): fixed-size tiles of 2^bits cells a side, one scale per pass, and
// in each pass a fixed-step march instead of the exact DDA. Pass k looks only inside the cell the
// coarser pass k-1 found: it samples the ray where it enters that cell and then where it enters
// each following slab of the ray's dominant axis (the "parallelogram": the step advances one cell
// along that axis, so a ray crossing the tile takes exactly 2^bits samples), and the first sample
// in an occupied cell is the pixel's hit at this scale. Cells a ray crosses inside a slab without a
// sample are never looked at, which is where the method loses against octreeTraverse
// (octree_walk.h).
//
// The includer defines what octree_render.h needs (the walk, octreeEntry, octreeLeafSrgb).
#ifndef LUXEL_GPU_SHARED_OCTREE_TILES_H
#define LUXEL_GPU_SHARED_OCTREE_TILES_H

#include "glsl_compat.h"
#include "octree_render.h"
#include "octree_tiles_layout.h"

LUXEL_SHARED_BEGIN

// Point query from the root: the entry whose cube (2^level voxels, or a wider leaf) holds voxel
// `v`. Its value is returned in `value`: a branch (>= 256) has something inside, a leaf is uniform.
LUXEL_FUNC uint octreeTileQuery(LUXEL_OCTREE tree, int depth, ivec3 v, int level,
                                LUXEL_INOUT(uint) value) {
    int l = depth - 1;  // the entries of the octant being read are 2^l voxels wide
    uint entry = uint(octreeSlot(v, l));
    value = octreeEntry(tree, entry);
    while (value >= LUXEL_OCTREE_LEAF_LIMIT && l > level) {
        l -= 1;
        entry = value - LUXEL_OCTREE_BRANCH_BIAS + uint(octreeSlot(v, l));
        value = octreeEntry(tree, entry);
    }
    return entry;
}

// The part [t0, t1] (t0 >= 0) of the ray inside the box [lo, hi); false when it misses.
LUXEL_FUNC bool octreeTileClip(LUXEL_REAL3 o, LUXEL_REAL3 d, ivec3 lo, ivec3 hi,
                               LUXEL_INOUT(LUXEL_REAL) t0, LUXEL_INOUT(LUXEL_REAL) t1) {
    t0 = LUXEL_REAL(0);
    t1 = LUXEL_REAL(LUXEL_INFINITY);
    for (int a = 0; a < 3; ++a) {
        if (d[a] == LUXEL_REAL(0)) {
            if (!(o[a] >= LUXEL_REAL(lo[a]) && o[a] < LUXEL_REAL(hi[a]))) return false;
            continue;
        }
        const LUXEL_REAL inv = LUXEL_REAL(1) / d[a];
        LUXEL_REAL ta = (LUXEL_REAL(lo[a]) - o[a]) * inv;
        LUXEL_REAL tb = (LUXEL_REAL(hi[a]) - o[a]) * inv;
        if (ta > tb) {
            const LUXEL_REAL swap = ta;
            ta = tb;
            tb = swap;
        }
        t0 = max(t0, ta);
        t1 = min(t1, tb);
    }
    return t0 <= t1;
}

// The cell (2^level voxels) holding the point at coordinate `x` on an axis stepped by `stp`: on a
// boundary, a ray moving down is in the lower cell (voxelStart's rule).
LUXEL_FUNC int octreeTileCellOf(LUXEL_REAL x, int stp, int level) {
    int f = voxelFloorToInt(clamp(x, LUXEL_REAL(-2), LUXEL_REAL(65538)));
    if (LUXEL_REAL(f) == x && stp < 0) f -= 1;
    return f >> level;
}

// One scale pass for one pixel: `s` is what pass `pass - 1` left (ignored for pass 0, whose
// "cell" is the content box). Cells are 2^level voxels; the previous pass's are 2^parentLevel.
LUXEL_FUNC OctreeTileState octreeTilesPass(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p,
                                           LUXEL_REAL3 o, LUXEL_REAL3 d, OctreeTileState s,
                                           uint pass, int level, int parentLevel) {
    const ivec3 size = octreeParamsSize(p);
    if (pass == 0u) s = OctreeTileState(LUXEL_OCTREE_TILE_MISS, 0, 0, 0, 0u, 0u, 0u, 0u);
    s.pass = pass + 1u;
    if (pass > 0u && s.status != LUXEL_OCTREE_TILE_FOUND) return s;
    ivec3 lo = ivec3(0);
    ivec3 hi = size;
    if (pass > 0u) {
        lo = ivec3(s.cellX, s.cellY, s.cellZ) * (1 << parentLevel);
        hi = min(lo + ivec3(1 << parentLevel), size);
    }
    s.status = pass == 0u ? LUXEL_OCTREE_TILE_MISS : LUXEL_OCTREE_TILE_DEAD_END;
    LUXEL_REAL t0 = LUXEL_REAL(0);
    LUXEL_REAL t1 = LUXEL_REAL(0);
    if (!octreeTileClip(o, d, lo, hi, t0, t1)) return s;
    // The cells of the box at this scale, and the dominant axis (lowest on ties).
    const ivec3 first = ivec3(lo.x >> level, lo.y >> level, lo.z >> level);
    const ivec3 last = ivec3((hi.x - 1) >> level, (hi.y - 1) >> level, (hi.z - 1) >> level);
    const ivec3 stp = ivec3(d.x > LUXEL_REAL(0) ? 1 : (d.x < LUXEL_REAL(0) ? -1 : 0),
                            d.y > LUXEL_REAL(0) ? 1 : (d.y < LUXEL_REAL(0) ? -1 : 0),
                            d.z > LUXEL_REAL(0) ? 1 : (d.z < LUXEL_REAL(0) ? -1 : 0));
    int a = 0;
    if (abs(d.y) > abs(d[a])) a = 1;
    if (abs(d.z) > abs(d[a])) a = 2;
    const int tiles = 1 << (parentLevel - level);  // the most slabs a tile has on one axis
    LUXEL_REAL t = t0;
    int slab = 0;
    for (int j = 0; j < tiles; ++j) {
        ivec3 cell = ivec3(0);
        for (int b = 0; b < 3; ++b) {
            const LUXEL_REAL x = t == LUXEL_REAL(0) ? o[b] : o[b] + t * d[b];
            cell[b] = clamp(octreeTileCellOf(x, stp[b], level), first[b], last[b]);
        }
        if (j == 0) slab = cell[a];
        cell[a] = slab;  // the dominant axis is the slab's, not a rounded coordinate
        s.samples += 1u;
        uint value = 0u;
        const uint entry =
            octreeTileQuery(tree, int(p.depth),
                            ivec3(cell.x << level, cell.y << level, cell.z << level), level, value);
        // A branch (value >= 256) is above every threshold: something is inside.
        if (value >= p.threshold) {
            s.status = LUXEL_OCTREE_TILE_FOUND;
            s.cellX = cell.x;
            s.cellY = cell.y;
            s.cellZ = cell.z;
            s.level = uint(level);
            s.entry = entry;
            return s;
        }
        // The next sample: where the ray enters the next slab of the dominant axis.
        slab += stp[a];
        if (slab < first[a] || slab > last[a]) break;
        const int plane = (stp[a] > 0 ? slab : slab + 1) << level;
        t = (LUXEL_REAL(plane) - o[a]) / d[a];
        if (!(t < t1)) break;
    }
    return s;
}

// The pixel's colour from its state: the found cell's box shaded as the surface mode shades a
// hit (octreeShadeSurface, octree_render.h: Lambert with sky light and the sun's visibility
// through the exact walk), or the sky. A coarse cell that is a branch has no colour of its own:
// it is drawn the light grey of trees without colours (the frames before the last pass).
LUXEL_FUNC vec3 octreeTilesShade(LUXEL_OCTREE tree, LUXEL_IN(OctreeRenderParams) p, LUXEL_REAL3 o,
                                 LUXEL_REAL3 d, OctreeTileState s, uint pixel) {
    if (s.status != LUXEL_OCTREE_TILE_FOUND) return octreeSky(p);
    const int width = 1 << int(s.level);
    const ivec3 lo = ivec3(s.cellX, s.cellY, s.cellZ) * width;
    const ivec3 hi = lo + ivec3(width);
    // The entry face: the last near plane the ray crosses (none for an origin inside).
    int axis = -1;
    LUXEL_REAL tNear = LUXEL_REAL(0);
    for (int a = 0; a < 3; ++a) {
        if (d[a] == LUXEL_REAL(0)) continue;
        const LUXEL_REAL t = (LUXEL_REAL(d[a] > LUXEL_REAL(0) ? lo[a] : hi[a]) - o[a]) / d[a];
        if (t >= tNear) {
            tNear = t;
            axis = a;
        }
    }
    LUXEL_REAL3 point = o;
    for (int a = 0; a < 3; ++a) {
        const LUXEL_REAL x = tNear == LUXEL_REAL(0) ? o[a] : o[a] + tNear * d[a];
        point[a] = clamp(x, LUXEL_REAL(lo[a]), LUXEL_REAL(hi[a]));
    }
    vec3 normal = vec3(0.0f);
    if (axis >= 0) {
        normal[axis] = d[axis] > LUXEL_REAL(0) ? -1.0f : 1.0f;
        point[axis] = LUXEL_REAL(d[axis] > LUXEL_REAL(0) ? lo[axis] : hi[axis]);
    }
    const uint value = octreeEntry(tree, s.entry);
    const vec3 albedo =
        value < LUXEL_OCTREE_LEAF_LIMIT
            ? octreeLeafColour(tree, octreeColourIndex(tree, int(p.depth), lo, s.entry))
            : vec3(octreeSrgbToLinear(0.8f));
    const vec3 sun = vec3(p.sunX, p.sunY, p.sunZ);
    const float cosine = axis >= 0 ? max(dot(normal, sun), 0.0f) : 1.0f;
    float visibility = 1.0f;
    if (cosine > 0.0f && (p.flags & LUXEL_OCTREE_SHADOWS) != 0u) {
        visibility = octreeSunVisibility(tree, p, point, pixel);
    }
    return albedo *
           (octreeSky(p) * p.ambient + vec3(p.sunR, p.sunG, p.sunB) * (cosine * visibility));
}

LUXEL_SHARED_END

#endif
