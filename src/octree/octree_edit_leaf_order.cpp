// OctreeEditor::set for the LeafOrder layout (octree_edit.h): the path is rebuilt as for PerEntry
// trees, and the colours of the leaves it replaces are spliced in leaf order.
#include <algorithm>
#include <vector>

#include "luxel/octree/octree_edit.h"
#include "octant_table.h"
#include "octree/leaf_order.h"

namespace luxel::octree {

Status OctreeEditor::setLeafOrder(Int3 cell, std::uint8_t opacity, Colour colour) {
    Octree& t = *tree_;
    if (opacity == 0) colour = Colour{};
    // The path: each octant, the slot taken in it and the leaf index where the octant starts.
    struct Step {
        std::uint32_t base;
        int slot;
        std::uint32_t first;
    };
    std::vector<Step> path;
    std::uint32_t base = 0, first = 0;
    int level = t.depth - 1;  // entries of the current octant are 2^level wide
    for (;; --level) {
        const int slot = childSlot(cell.x, cell.y, cell.z, level);
        path.push_back({base, slot, first});
        first += leavesBefore(t, base, slot);
        const std::uint32_t v = t.nodes[base + slot];
        if (isLeaf(v) || level == 0) break;
        base = childBase(v);
    }
    const std::uint32_t leafIndex = first;
    const Step& last = path.back();
    const std::uint32_t oldValue = t.nodes[last.base + last.slot];
    const Colour oldColour = t.colours[leafIndex];
    if (oldValue == opacity && oldColour == colour) return Ok{};

    // The change to the colours: [spliceBegin, spliceEnd) of the old array becomes `seq`.
    std::uint64_t spliceBegin = leafIndex, spliceEnd = leafIndex + 1;
    std::vector<Colour> seq{colour};
    std::uint32_t entry = opacity;
    bool ok = true;
    // A leaf wider than a voxel splits into octants of the old leaf down to the voxel. They never
    // collapse: the new voxel differs from the old leaf in opacity or colour.
    for (int l = 0; l < level && ok; ++l) {
        std::uint32_t entries[8];
        std::fill(entries, entries + 8, oldValue);
        const int slot = childSlot(cell.x, cell.y, cell.z, l);
        entries[slot] = entry;
        seq.insert(seq.begin(), static_cast<std::size_t>(slot), oldColour);
        seq.insert(seq.end(), static_cast<std::size_t>(7 - slot), oldColour);
        const std::uint32_t b = internLeafOrder(*table_, t, entries);
        ok = b != 0;
        entry = branchTo(b);
    }
    // Back up the path; the root octant is rewritten in place.
    for (std::size_t k = path.size(); k-- > 0 && ok;) {
        const Step s = path[k];
        std::uint32_t entries[8];
        for (int i = 0; i < 8; ++i) entries[i] = t.nodes[s.base + i];
        entries[s.slot] = entry;
        if (s.base == 0) {
            for (int i = 0; i < 8; ++i) t.nodes[i] = entries[i];
            break;
        }
        // Collapse when all 8 are one leaf of one colour; then every sibling is a leaf, at
        // first + j before the slot and just past the replaced range after it.
        bool uniform = isLeaf(entry);
        for (int j = 0; j < 8 && uniform; ++j) {
            if (j == s.slot) continue;
            const std::uint64_t at = j < s.slot ? s.first + j : spliceEnd + (j - s.slot - 1);
            uniform = entries[j] == entry && t.colours[at] == seq[0];
        }
        if (uniform) {
            spliceEnd += 7 - s.slot;
            spliceBegin = s.first;
            seq.resize(1);
            continue;  // `entry` stays the leaf
        }
        const std::uint32_t b = internLeafOrder(*table_, t, entries);
        ok = b != 0;
        entry = branchTo(b);
    }
    if (!ok) return Error("octree edit: more than 2^32 entries; compact() or rebuild the tree");
    const auto at = t.colours.begin() + static_cast<std::ptrdiff_t>(spliceBegin);
    t.colours.erase(at, t.colours.begin() + static_cast<std::ptrdiff_t>(spliceEnd));
    t.colours.insert(t.colours.begin() + static_cast<std::ptrdiff_t>(spliceBegin), seq.begin(),
                     seq.end());
    t.leafCounts[0] = static_cast<std::uint32_t>(octantLeaves(t, t.nodes.data()));
    return Ok{};
}

}  // namespace luxel::octree
