#include "luxel/octree/octree_edit.h"

#include <unordered_map>
#include <vector>

#include "octant_table.h"

namespace luxel::octree {

OctreeEditor::OctreeEditor(Octree tree)
    : tree_(std::make_unique<Octree>(std::move(tree))),
      table_(std::make_unique<OctantTable>(*tree_)) {}

OctreeEditor::~OctreeEditor() = default;
OctreeEditor::OctreeEditor(OctreeEditor&&) noexcept = default;
OctreeEditor& OctreeEditor::operator=(OctreeEditor&&) noexcept = default;

// The entry standing for an octant with these contents: one leaf when all 8 are the same leaf
// (the builder's collapse), else the interned octant.
std::uint32_t OctreeEditor::entryFor(const std::uint32_t* entries, const Colour* colours,
                                     Colour& leafColour, bool& ok) {
    bool uniform = isLeaf(entries[0]);
    for (int i = 1; i < 8 && uniform; ++i) {
        uniform = entries[i] == entries[0] && (!colours || colours[i] == colours[0]);
    }
    if (uniform) {
        leafColour = colours ? colours[0] : Colour{};
        return entries[0];
    }
    leafColour = Colour{};
    const std::uint32_t base = table_->intern(entries, colours);
    if (base == 0) ok = false;
    return branchTo(base);
}

Status OctreeEditor::set(Int3 cell, std::uint8_t opacity, Colour colour) {
    Octree& t = *tree_;
    const bool colours = t.hasColours();
    if (opacity == 0 || !colours) colour = Colour{};
    // The path: the octant at each level and the slot taken in it, down to a leaf.
    struct Step {
        std::uint32_t base;
        int slot;
    };
    std::vector<Step> path;
    std::uint32_t base = 0;
    int level = t.depth - 1;  // entries of the current octant are 2^level wide
    for (;; --level) {
        const int slot = childSlot(cell.x, cell.y, cell.z, level);
        path.push_back({base, slot});
        const std::uint32_t v = t.nodes[base + slot];
        if (isLeaf(v) || level == 0) break;
        base = childBase(v);
    }
    const Step& last = path.back();
    const std::uint32_t oldValue = t.nodes[last.base + last.slot];
    const Colour oldColour = colours ? t.colours[last.base + last.slot] : Colour{};
    if (oldValue == opacity && oldColour == colour) return Ok{};

    bool ok = true;
    std::uint32_t entry = opacity;
    Colour entryColour = colour;
    // A leaf wider than a voxel splits: octants filled with the old leaf, down to the voxel.
    for (int l = 0; l < level; ++l) {
        std::uint32_t entries[8];
        Colour cs[8];
        for (int i = 0; i < 8; ++i) {
            entries[i] = oldValue;
            cs[i] = oldColour;
        }
        const int slot = childSlot(cell.x, cell.y, cell.z, l);
        entries[slot] = entry;
        cs[slot] = entryColour;
        entry = entryFor(entries, colours ? cs : nullptr, entryColour, ok);
    }
    // Back up the path; the root octant is rewritten in place.
    for (std::size_t k = path.size(); k-- > 0;) {
        const Step s = path[k];
        std::uint32_t entries[8];
        Colour cs[8];
        for (int i = 0; i < 8; ++i) {
            entries[i] = t.nodes[s.base + i];
            cs[i] = colours ? t.colours[s.base + i] : Colour{};
        }
        entries[s.slot] = entry;
        cs[s.slot] = entryColour;
        if (s.base == 0) {
            for (int i = 0; i < 8; ++i) {
                t.nodes[i] = entries[i];
                if (colours) t.colours[i] = cs[i];
            }
            break;
        }
        entry = entryFor(entries, colours ? cs : nullptr, entryColour, ok);
    }
    if (!ok) return Error("octree edit: more than 2^32 entries; compact() or rebuild the tree");
    return Ok{};
}

Octree compacted(const Octree& tree) {
    Octree out;
    out.depth = tree.depth;
    out.size = tree.size;
    out.nodes.assign(8, 0);
    if (tree.hasColours()) out.colours.assign(8, Colour{});
    std::unordered_map<std::uint32_t, std::uint32_t> moved{{0u, 0u}};  // old base -> new base
    // Depth-first with an explicit stack of (old base, new base) octants whose entries to copy.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> todo{{0u, 0u}};
    while (!todo.empty()) {
        const auto [from, to] = todo.back();
        todo.pop_back();
        for (int i = 0; i < 8; ++i) {
            const std::uint32_t v = tree.nodes[from + i];
            if (tree.hasColours()) out.colours[to + i] = tree.colours[from + i];
            if (isLeaf(v)) {
                out.nodes[to + i] = v;
                continue;
            }
            auto [it, fresh] = moved.emplace(childBase(v), 0);
            if (fresh) {
                it->second = static_cast<std::uint32_t>(out.nodes.size());
                out.nodes.resize(out.nodes.size() + 8, 0);
                if (tree.hasColours()) out.colours.resize(out.nodes.size());
                todo.push_back({childBase(v), it->second});
            }
            out.nodes[to + i] = branchTo(it->second);
        }
    }
    return out;
}

void OctreeEditor::compact() {
    *tree_ = compacted(*tree_);
    table_->reindex();
}

}  // namespace luxel::octree
