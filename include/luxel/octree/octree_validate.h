// Checks an untrusted octree array (a file, a network buffer) before anything walks it: the
// traversal and the renderers assume a validated tree and do no checks of their own.
#pragma once

#include <cstdint>
#include <span>

#include "luxel/core/error.h"
#include "luxel/octree/octree.h"

namespace luxel::octree {

// Ok when the array is a well-formed tree of `depth` (1..kMaxDepth): a non-empty multiple of 8
// entries; every branch points inside the array at a multiple of 8 (never at the root: branches
// are at least 256, so their targets at least 8); no octant reaches itself (the DAG has no
// cycle); no path from the root is deeper than `depth` (entries of octants at the voxel level are
// leaves); and `colourCount` is 0 or the entry count.
// The error names the first problem and the entry where it is, e.g.
// "octree entry 13: branch 301 points to index 53, not the start of an octant".
// Runs in time and memory linear in the array.
Status validateOctree(std::span<const std::uint32_t> nodes, int depth,
                      std::uint64_t colourCount = 0);
// The same, plus the content box: zero, or each side in 1..2^depth; and for the LeafOrder layout
// the attribute index: one leaf count per octant, each equal to the leaves of its subtree
// (recomputed), and one colour per leaf of the expanded tree.
Status validateOctree(const Octree& tree);
// The LeafOrder checks alone, on a tree whose array validateOctree(nodes, depth) accepted.
Status validateLeafOrder(const Octree& tree);

}  // namespace luxel::octree
