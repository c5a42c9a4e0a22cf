// Exact ray traversal of the sparse voxel octree (include/luxel/octree/octree.h), shared by the
// CPU (double) and the GPU (float). The ray walks the cells of the octree's cube with the
// Amanatides & Woo walk of voxel_walk.h; at each cell it finds the leaf holding it through an
// ancestor stack (a move restarts the descent at the lowest octant holding both the old and the
// new cell: the highest differing coordinate bit gives its level, ESVO's POP, Laine & Karras
// 2010), and a leaf wider than a voxel is left in one exact jump (voxelLeaveBox). The cells
// visited, and so every hit, are the per-voxel walk's (docs/algorithms/sparse-voxel-octree.md).
//
// The includer defines, besides what voxel_walk.h needs:
// - LUXEL_OCTREE: the type of the tree handle passed through to the accessor;
// - uint octreeEntry(LUXEL_OCTREE tree, uint index): entry `index` of the array;
// - bool octreeLeafOrder(LUXEL_OCTREE tree): colours are in leaf order
// (AttributeLayout::LeafOrder);
// - uint octreeLeafCount(LUXEL_OCTREE tree, uint octant): leaves below octant `octant` (base / 8).
// In leaf order a leaf's colour index is its depth-first order, the sibling counts of the octants
// descended through (octreeColourIndex), never an expansion of the DAG
// (docs/algorithms/sparse-voxel-octree.md §1 "Colour"); the walk itself does not pay for it.
#ifndef LUXEL_GPU_SHARED_OCTREE_WALK_H
#define LUXEL_GPU_SHARED_OCTREE_WALK_H

#include "glsl_compat.h"
#include "voxel_walk.h"

#define LUXEL_OCTREE_MAX_DEPTH 16
#define LUXEL_OCTREE_LEAF_LIMIT 256u
#define LUXEL_OCTREE_BRANCH_BIAS 248u

LUXEL_SHARED_BEGIN

// The leaf found for a cell: its entry, its value (opacity 0..255), its cube
// [origin, origin + 2^level), and the index of its colour (its leaf order in a LeafOrder tree,
// else its entry).
struct OctreeLeaf {
    uint entry;
    uint value;
    int level;
    ivec3 origin;
    uint colourIndex;
};

// The octants above the last cell looked up: base[L] is the first entry of the octant of level L
// (entries 2^(L-1) wide; the root is level depth) holding it, valid for L in [deepest, depth].
struct OctreeCursor {
    uint base[LUXEL_OCTREE_MAX_DEPTH + 1];
    int deepest;
    ivec3 last;
};

LUXEL_FUNC_HOT int octreeSlot(ivec3 c, int level) {
    return ((c.x >> level) & 1) | (((c.z >> level) & 1) << 1) | (((c.y >> level) & 1) << 2);
}

// Only the root's slot is read before a descent writes the levels below it.
LUXEL_FUNC void octreeCursorReset(LUXEL_INOUT(OctreeCursor) cursor, int depth) {
    cursor.base[depth] = 0u;
    cursor.deepest = depth;
    cursor.last = ivec3(0);
}

// Leaves of the expanded tree before `slot` in the octant at `base`: 1 per leaf, the child's
// count per branch.
LUXEL_FUNC_HOT uint octreeLeavesBefore(LUXEL_OCTREE tree, uint base, int slot) {
    uint n = 0u;
    for (int j = 0; j < slot; ++j) {
        const uint e = octreeEntry(tree, base + uint(j));
        n += e < LUXEL_OCTREE_LEAF_LIMIT
                 ? 1u
                 : octreeLeafCount(tree, (e - LUXEL_OCTREE_BRANCH_BIAS) >> 3u);
    }
    return n;
}

// The leaf holding `cell` (inside the cube). Starts at the lowest octant still holding the cell.
// One exit at the end: the cursor is written back there only (an early return from inside the
// loop lost the stack writes under Mesa's lavapipe). The leaf's colourIndex is its entry: a
// LeafOrder tree's leaf order costs sibling counts at every level, so it is found only for the
// leaves whose colour is read (octreeColourIndex).
LUXEL_FUNC_HOT OctreeLeaf octreeLocate(LUXEL_OCTREE tree, int depth,
                                       LUXEL_INOUT(OctreeCursor) cursor, ivec3 cell) {
    const int diff = (cell.x ^ cursor.last.x) | (cell.y ^ cursor.last.y) | (cell.z ^ cursor.last.z);
    int level = clamp(findMSB(diff) + 1, cursor.deepest, depth);
    uint entry = cursor.base[level] + uint(octreeSlot(cell, level - 1));
    uint value = octreeEntry(tree, entry);
    while (value >= LUXEL_OCTREE_LEAF_LIMIT && level > 1) {
        const uint base = value - LUXEL_OCTREE_BRANCH_BIAS;
        level -= 1;
        cursor.base[level] = base;
        entry = base + uint(octreeSlot(cell, level - 1));
        value = octreeEntry(tree, entry);
    }
    cursor.deepest = level;
    cursor.last = cell;
    const int mask = ~((1 << (level - 1)) - 1);
    return OctreeLeaf(entry, value < LUXEL_OCTREE_LEAF_LIMIT ? value : 0u, level - 1,
                      ivec3(cell.x & mask, cell.y & mask, cell.z & mask), entry);
}

// The colour index of the leaf at `entry` holding `cell`: the entry itself, or in a LeafOrder tree
// its depth-first leaf order, summed over the octants from the root down to it.
LUXEL_FUNC_HOT uint octreeColourIndex(LUXEL_OCTREE tree, int depth, ivec3 cell, uint entry) {
    if (!octreeLeafOrder(tree)) return entry;
    uint base = 0u;
    uint first = 0u;
    for (int level = depth - 1; level >= 0; --level) {
        const int slot = octreeSlot(cell, level);
        first += octreeLeavesBefore(tree, base, slot);
        const uint value = octreeEntry(tree, base + uint(slot));
        if (value < LUXEL_OCTREE_LEAF_LIMIT || level == 0) break;
        base = value - LUXEL_OCTREE_BRANCH_BIAS;
    }
    return first;
}

// The walk and the cursor of one ray through the octree.
struct OctreeRay {
    VoxelWalk walk;
    OctreeCursor cursor;
    int depth;
};

// Starts a ray o + t d (d finite and non-zero) through the content box [0, size) of the cube
// [0, 2^depth)^3 (the walk's world, so its clipping and boundary rules are the dense world's);
// false on a miss.
LUXEL_FUNC_HOT bool octreeRayStart(LUXEL_INOUT(OctreeRay) r, int depth, ivec3 size, LUXEL_REAL3 o,
                                   LUXEL_REAL3 d, LUXEL_REAL tMax) {
    r.depth = depth;
    r.walk.o = o;
    r.walk.d = d;
    r.walk.inv = LUXEL_REAL3(LUXEL_REAL(1) / d.x, LUXEL_REAL(1) / d.y, LUXEL_REAL(1) / d.z);
    r.walk.size = size;
    octreeCursorReset(r.cursor, depth);
    return voxelStart(r.walk, tMax);
}

// The last cell of the leaf's cube on each axis, within the content box.
LUXEL_FUNC_HOT ivec3 octreeLeafLast(LUXEL_IN(OctreeRay) r, OctreeLeaf leaf) {
    const int last = (1 << leaf.level) - 1;
    return min(leaf.origin + ivec3(last), r.walk.size - ivec3(1));
}

// Leaves the leaf's cube: one A&W step for a voxel, one exact jump for a wider leaf. False when
// the ray leaves the content box or passes tMax.
LUXEL_FUNC_HOT bool octreeRayLeave(LUXEL_INOUT(OctreeRay) r, OctreeLeaf leaf, LUXEL_REAL tMax) {
    if (leaf.level == 0) return voxelStepOne(r.walk, tMax);
    return voxelLeaveBox(r.walk, leaf.origin, octreeLeafLast(r, leaf), tMax);
}

// The t at which the ray leaves the current leaf (for the length of its path inside it).
LUXEL_FUNC_HOT LUXEL_REAL octreeLeafExitT(LUXEL_IN(OctreeRay) r, OctreeLeaf leaf) {
    LUXEL_REAL t = LUXEL_REAL(LUXEL_INFINITY);
    const ivec3 last = octreeLeafLast(r, leaf);
    for (int a = 0; a < 3; ++a) {
        if (r.walk.stp[a] == 0) continue;
        const int c = r.walk.stp[a] > 0 ? last[a] : leaf.origin[a];
        t = min(t, voxelExitT(c, r.walk.stp[a], r.walk.o[a], r.walk.inv[a]));
    }
    return t;
}

// The first cell whose leaf opacity is at least `threshold` (1: any non-empty voxel) with entry
// t in [0, tMax], within `cap` loop iterations (leaves visited); the hit's entry index and colour
// index are returned in `entry` and `colourIndex` (0 on a miss).
LUXEL_FUNC_HOT VoxelTrace octreeTraverseLeaf(LUXEL_OCTREE tree, int depth, ivec3 size,
                                             LUXEL_REAL3 o, LUXEL_REAL3 d, LUXEL_REAL tMax, int cap,
                                             uint threshold, LUXEL_INOUT(uint) entry,
                                             LUXEL_INOUT(uint) colourIndex) {
    OctreeRay r;
    entry = 0u;
    colourIndex = 0u;
    if (!octreeRayStart(r, depth, size, o, d, tMax)) return voxelMiss(0, false);
    int steps = 0;
    for (;;) {
        if (steps >= cap) return voxelMiss(steps, true);
        ++steps;
        const OctreeLeaf leaf = octreeLocate(tree, depth, r.cursor, r.walk.cell);
        if (leaf.value >= threshold) {
            entry = leaf.entry;
            colourIndex = octreeColourIndex(tree, depth, r.walk.cell, leaf.entry);
            return VoxelTrace(true, false, r.walk.cell, r.walk.t, r.walk.axis, voxelStep(r.walk),
                              steps);
        }
        if (!octreeRayLeave(r, leaf, tMax)) return voxelMiss(steps, false);
    }
}

// octreeTraverseLeaf without the colour index.
LUXEL_FUNC_HOT VoxelTrace octreeTraverse(LUXEL_OCTREE tree, int depth, ivec3 size, LUXEL_REAL3 o,
                                         LUXEL_REAL3 d, LUXEL_REAL tMax, int cap, uint threshold,
                                         LUXEL_INOUT(uint) entry) {
    uint colourIndex = 0u;
    return octreeTraverseLeaf(tree, depth, size, o, d, tMax, cap, threshold, entry, colourIndex);
}

LUXEL_SHARED_END

#endif
