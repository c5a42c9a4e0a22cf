#include "luxel/octree/octree.h"

#include <unordered_map>
#include <vector>

#include "octree/octree_access.h"  // with the shared traversal kernel

namespace luxel::octree {

const char* attributeLayoutName(AttributeLayout layout) {
    switch (layout) {
        case AttributeLayout::None:
            return "none";
        case AttributeLayout::PerEntry:
            return "per-entry";
        case AttributeLayout::LeafOrder:
            return "leaf-order";
    }
    return "none";
}

Leaf findLeaf(const Octree& tree, Int3 cell) {
    std::uint32_t base = 0;
    for (int level = tree.depth - 1; level >= 0; --level) {
        const int slot = childSlot(cell.x, cell.y, cell.z, level);
        const std::uint32_t entry = base + slot;
        const std::uint32_t value = tree.nodes[entry];
        if (isLeaf(value) || level == 0) {
            const int mask = ~((1 << level) - 1);
            // The leaf order, where colours use it, as the traversal kernel finds it.
            const std::uint32_t colourIndex = gpu::shared::octreeColourIndex(
                arraysOf(tree), tree.depth, gpu::shared::ivec3(cell.x, cell.y, cell.z), entry);
            return {entry, colourIndex, static_cast<std::uint8_t>(isLeaf(value) ? value : 0), level,
                    Int3(cell.x & mask, cell.y & mask, cell.z & mask)};
        }
        base = childBase(value);
    }
    return {};
}

std::uint8_t opacityAt(const Octree& tree, Int3 cell) {
    return findLeaf(tree, cell).opacity;
}

Colour colourAt(const Octree& tree, Int3 cell) {
    if (!tree.hasColours()) return {};
    return tree.colours[findLeaf(tree, cell).colourIndex];
}

namespace {

// Counts over the expanded tree, memoised per (octant, level): a DAG shares octants, and the same
// octant may even stand at several levels (its entries then cover cubes of different sizes).
class Counter {
  public:
    explicit Counter(const Octree& tree) : tree_(tree) {}

    struct Counts {
        std::uint64_t solid = 0;    // solid voxels below
        std::uint64_t octants = 0;  // octants below, this one included
    };

    // The octant at `base` whose entries are 2^level voxels wide.
    Counts count(std::uint32_t base, int level) {
        const std::uint64_t key = (static_cast<std::uint64_t>(base) << 5) | level;
        if (auto it = memo_.find(key); it != memo_.end()) return it->second;
        Counts c;
        c.octants = 1;
        const std::uint64_t voxels = std::uint64_t{1} << (3 * level);
        for (int i = 0; i < 8; ++i) {
            const std::uint32_t value = tree_.nodes[base + i];
            if (isLeaf(value)) {
                if (value > 0) c.solid += voxels;
            } else if (level > 0) {
                const Counts child = count(childBase(value), level - 1);
                c.solid += child.solid;
                c.octants += child.octants;
            }
        }
        memo_.emplace(key, c);
        return c;
    }

    std::uint64_t reachable() const {
        std::vector<bool> seen(tree_.nodes.size() / 8, false);
        std::vector<std::uint32_t> todo{0};
        std::uint64_t n = 0;
        while (!todo.empty()) {
            const std::uint32_t base = todo.back();
            todo.pop_back();
            if (seen[base / 8]) continue;
            seen[base / 8] = true;
            ++n;
            for (int i = 0; i < 8; ++i) {
                const std::uint32_t value = tree_.nodes[base + i];
                if (!isLeaf(value)) todo.push_back(childBase(value));
            }
        }
        return n;
    }

  private:
    const Octree& tree_;
    std::unordered_map<std::uint64_t, Counts> memo_;
};

}  // namespace

OctreeStats measure(const Octree& tree) {
    OctreeStats s;
    s.depth = tree.depth;
    s.octants = tree.nodes.size() / 8;
    s.geometryBytes = tree.nodes.size() * sizeof(std::uint32_t);
    s.layout = tree.attributes();
    s.attributeBytes = tree.colours.size() * sizeof(Colour);
    if (tree.leafOrder()) s.attributeIndexBytes = tree.leafCounts.size() * sizeof(std::uint32_t);
    const std::uint64_t side = static_cast<std::uint64_t>(tree.side());
    s.totalVoxels = side * side * side;
    if (tree.nodes.size() < 8) return s;
    Counter counter(tree);
    const Counter::Counts root = counter.count(0, tree.depth - 1);
    s.solidVoxels = root.solid;
    s.expandedOctants = root.octants;
    s.reachable = counter.reachable();
    const double bits = 8.0 * static_cast<double>(s.geometryBytes);
    s.bitsPerSolidVoxel = s.solidVoxels > 0 ? bits / static_cast<double>(s.solidVoxels) : 0.0;
    s.bitsPerVoxel = bits / static_cast<double>(s.totalVoxels);
    return s;
}

}  // namespace luxel::octree
