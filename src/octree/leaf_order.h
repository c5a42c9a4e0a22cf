// The LeafOrder attribute layout (octree.h, docs/algorithms/sparse-voxel-octree.md §1 "Colour"):
// colours one per leaf of the expanded tree in depth-first order, found during a descent from
// per-octant subtree leaf counts (Dolonius, Sintorn, Kämpe and Assarsson, "Compressing color data
// for voxelized surface geometry", 2017). Shared by the builder, the editor and the accessors.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_build.h"

namespace luxel::octree {

class OctantTable;

// Leaves below one entry of a LeafOrder tree: 1 for a leaf, the child's count for a branch.
inline std::uint64_t entryLeaves(const Octree& tree, std::uint32_t entry) {
    return isLeaf(entry) ? 1 : tree.leafCounts[childBase(entry) / 8];
}

// Leaves of an octant with these 8 entries (its children's counts must be known).
std::uint64_t octantLeaves(const Octree& tree, const std::uint32_t* entries);

// Leaves before `slot` in the octant at `base`: added to the octant's first leaf index when a
// descent takes that slot.
std::uint32_t leavesBefore(const Octree& tree, std::uint32_t base, int slot);

// Interns an octant keyed on its entries alone and records its leaf count when it is new. 0 when
// the array would outgrow the format or the count a uint32.
std::uint32_t internLeafOrder(OctantTable& table, Octree& tree, const std::uint32_t* entries);

// The builder for the LeafOrder layout (octree_build.cpp dispatches here).
Result<Octree> buildLeafOrderTree(const OctreeSource& source, const BuildOptions& options,
                                  int depth);

// The leaf counts of every octant recomputed from the array (depth-first, no recursion); entries
// of octants not reachable from the root are 0. Error when a count exceeds a uint32. `nodes`
// must be a validated tree.
Result<std::vector<std::uint32_t>> computeLeafCounts(const std::vector<std::uint32_t>& nodes);

}  // namespace luxel::octree
