#include "luxel/octree/octree_validate.h"

#include <string>
#include <vector>

#include "octree/leaf_order.h"

namespace luxel::octree {
namespace {

Error entryError(std::uint64_t entry, const std::string& problem) {
    return Error("octree entry " + std::to_string(entry) + ": " + problem);
}

}  // namespace

Status validateOctree(std::span<const std::uint32_t> nodes, int depth, std::uint64_t colourCount) {
    if (depth < 1 || depth > kMaxDepth) {
        return Error("octree depth " + std::to_string(depth) + " is outside 1.." +
                     std::to_string(kMaxDepth));
    }
    if (nodes.size() < 8 || nodes.size() % 8 != 0) {
        return Error("octree has " + std::to_string(nodes.size()) +
                     " entries; it needs a non-zero multiple of 8 (octants of 8 entries)");
    }
    if (colourCount != 0 && colourCount != nodes.size()) {
        return Error("octree has " + std::to_string(colourCount) + " colours for " +
                     std::to_string(nodes.size()) + " entries; it needs one per entry or none");
    }
    // Every branch target first, so the walk below only follows valid pointers.
    for (std::uint64_t i = 0; i < nodes.size(); ++i) {
        const std::uint32_t v = nodes[i];
        if (isLeaf(v)) continue;
        const std::uint64_t target = childBase(v);
        if (target % 8 != 0) {
            return entryError(i, "branch " + std::to_string(v) + " points to index " +
                                     std::to_string(target) + ", not the start of an octant");
        }
        if (target + 8 > nodes.size()) {
            return entryError(i, "branch " + std::to_string(v) + " points to index " +
                                     std::to_string(target) + ", past the end of the " +
                                     std::to_string(nodes.size()) + " entries");
        }
    }
    // Height of every reachable octant (1 = entries are all leaves) by an explicit post-order
    // walk; an octant met again while still open is a cycle.
    const std::uint64_t octants = nodes.size() / 8;
    constexpr std::uint8_t kOpen = 0xff;
    std::vector<std::uint8_t> height(octants, 0);  // 0 = not visited, kOpen = on the path
    struct Frame {
        std::uint32_t octant;
        int next;  // next slot to look at
    };
    std::vector<Frame> path{{0, 0}};
    height[0] = kOpen;
    while (!path.empty()) {
        Frame& f = path.back();
        if (f.next == 8) {
            int h = 1;
            for (int s = 0; s < 8; ++s) {
                const std::uint32_t v = nodes[f.octant * 8ull + s];
                if (!isLeaf(v)) h = std::max(h, height[childBase(v) / 8] + 1);
            }
            height[f.octant] = static_cast<std::uint8_t>(std::min(h, 254));
            path.pop_back();
            continue;
        }
        const std::uint64_t entry = f.octant * 8ull + f.next++;
        const std::uint32_t v = nodes[entry];
        if (isLeaf(v)) continue;
        const std::uint32_t child = childBase(v) / 8;
        if (height[child] == kOpen) {
            return entryError(entry, "branch " + std::to_string(v) + " points back to octant " +
                                         std::to_string(child * 8ull) +
                                         " on its own path (a cycle)");
        }
        if (height[child] != 0) continue;
        // The root is at path depth 1; a path longer than `depth` octants reaches past the voxels.
        if (static_cast<int>(path.size()) >= depth) {
            return entryError(entry,
                              "branch below the voxel level (the tree is deeper than its "
                              "depth " +
                                  std::to_string(depth) + ")");
        }
        height[child] = kOpen;
        path.push_back({child, 0});
    }
    if (height[0] > depth) {
        return Error("octree is " + std::to_string(height[0]) + " levels deep; its depth is " +
                     std::to_string(depth));
    }
    return Ok{};
}

Status validateLeafOrder(const Octree& tree) {
    const std::uint64_t octants = tree.nodes.size() / 8;
    if (tree.leafCounts.size() != octants) {
        return Error("octree has " + std::to_string(tree.leafCounts.size()) + " leaf counts for " +
                     std::to_string(octants) +
                     " octants; the leaf-order layout needs one per octant");
    }
    auto counts = computeLeafCounts(tree.nodes);
    if (!counts) return counts.error();
    for (std::uint64_t o = 0; o < octants; ++o) {
        // Octants the root does not reach (left by edits) are never walked: 0 = unreachable.
        if ((*counts)[o] == 0 || (*counts)[o] == tree.leafCounts[o]) continue;
        return Error("octree leaf count of octant " + std::to_string(o * 8) + " is " +
                     std::to_string(tree.leafCounts[o]) + " but its subtree has " +
                     std::to_string((*counts)[o]) + " leaves");
    }
    if (tree.colours.size() != (*counts)[0]) {
        return Error("octree has " + std::to_string(tree.colours.size()) +
                     " leaf-order colours for " + std::to_string((*counts)[0]) +
                     " leaves; it needs one per leaf");
    }
    return Ok{};
}

Status validateOctree(const Octree& tree) {
    const bool leafOrder = tree.layout == AttributeLayout::LeafOrder &&
                           (!tree.colours.empty() || !tree.leafCounts.empty());
    if (Status s = validateOctree(tree.nodes, tree.depth, leafOrder ? 0 : tree.colours.size());
        !s) {
        return s;
    }
    if (leafOrder) {
        if (Status s = validateLeafOrder(tree); !s) return s;
    }
    const Int3 size = tree.size;
    if (size.x == 0 && size.y == 0 && size.z == 0) return Ok{};
    const int side = 1 << tree.depth;
    for (int v : {size.x, size.y, size.z}) {
        if (v < 1 || v > side) {
            return Error("octree size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                         "x" + std::to_string(size.z) + " does not fit its " +
                         std::to_string(side) + "^3 cube");
        }
    }
    return Ok{};
}

}  // namespace luxel::octree
