// Editing a DAG octree voxel by voxel: a change rebuilds only the octants on the path from the
// root to the voxel (shared octants are never modified; the new path is interned like the
// builder's octants), so an edit costs O(depth) whatever the tree's size. The old path stays in
// the array until compact(). In the LeafOrder layout the edit also splices the leaf colours it
// adds or removes into the colour array (O(colours)) and records the new octants' leaf counts.
#pragma once

#include <memory>

#include "luxel/core/error.h"
#include "luxel/octree/octree.h"

namespace luxel::octree {

class OctantTable;

class OctreeEditor {
  public:
    explicit OctreeEditor(Octree tree);  // a validated tree
    ~OctreeEditor();
    OctreeEditor(OctreeEditor&&) noexcept;
    OctreeEditor& operator=(OctreeEditor&&) noexcept;

    // Sets one voxel (inside [0, side)^3); the colour is ignored in a tree without colours and
    // for opacity 0. Fails only when the array would outgrow the format.
    Status set(Int3 cell, std::uint8_t opacity, Colour colour = {});

    const Octree& tree() const { return *tree_; }
    // Rewrites the array with only the octants reachable from the root, in depth-first order.
    void compact();

  private:
    std::uint32_t entryFor(const std::uint32_t* entries, const Colour* colours, Colour& leafColour,
                           bool& ok);
    Status setLeafOrder(Int3 cell, std::uint8_t opacity, Colour colour);  // octree_edit_leaf_order

    std::unique_ptr<Octree> tree_;  // stable address: the table refers to it
    std::unique_ptr<OctantTable> table_;
};

// A copy with only the reachable octants, renumbered depth-first (root first).
Octree compacted(const Octree& tree);

}  // namespace luxel::octree
