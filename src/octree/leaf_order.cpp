#include "octree/leaf_order.h"

#include <limits>
#include <string>

#include "luxel/core/memory.h"
#include "octant_table.h"

namespace luxel::octree {

std::uint64_t octantLeaves(const Octree& tree, const std::uint32_t* entries) {
    std::uint64_t n = 0;
    for (int i = 0; i < 8; ++i) n += entryLeaves(tree, entries[i]);
    return n;
}

std::uint32_t leavesBefore(const Octree& tree, std::uint32_t base, int slot) {
    std::uint64_t n = 0;
    for (int j = 0; j < slot; ++j) n += entryLeaves(tree, tree.nodes[base + j]);
    return static_cast<std::uint32_t>(n);
}

std::uint32_t internLeafOrder(OctantTable& table, Octree& tree, const std::uint32_t* entries) {
    const std::uint64_t leaves = octantLeaves(tree, entries);
    if (leaves > std::numeric_limits<std::uint32_t>::max()) return 0;
    const std::uint32_t base = table.intern(entries, nullptr);
    if (base != 0 && base / 8 >= tree.leafCounts.size()) {
        tree.leafCounts.push_back(static_cast<std::uint32_t>(leaves));
    }
    return base;
}

namespace {

// The recursive bottom-up build of octree_build.cpp with the LeafOrder rules: an octant collapses
// only when its 8 leaves agree in opacity and colour (colours stay exact), octants are shared on
// their entries alone, and every call appends the colours of the leaves it returns, depth first,
// so `colours` ends in leaf order.
class LeafOrderBuilder {
  public:
    LeafOrderBuilder(const OctreeSource& source, Octree& tree, bool collapse)
        : source_(source), tree_(tree), table_(tree), collapse_(collapse), size_(source.size()) {}

    bool failed() const { return failed_; }
    const std::string& problem() const { return problem_; }

    // The entry for the cube [origin, origin + 2^level); its leaves' colours are appended.
    std::uint32_t build(Int3 origin, int level) {
        const bool outside = origin.x >= size_.x || origin.y >= size_.y || origin.z >= size_.z;
        if (outside && (collapse_ || level == 0)) return leaf(0, Colour{});
        if (level == 0) {
            std::uint8_t opacity = 0;
            Colour colour;
            source_.voxel(origin, opacity, colour);
            return leaf(opacity, colour);
        }
        if (auto uniform = collapse_ ? source_.uniformBlock(origin, level) : std::nullopt) {
            return leaf(uniform->opacity, uniform->colour);
        }
        const int half = 1 << (level - 1);
        const std::size_t mark = tree_.colours.size();
        std::uint32_t values[8];
        bool uniform = true;
        for (int slot = 0; slot < 8; ++slot) {
            const Int3 child(origin.x + (slot & 1) * half, origin.y + ((slot >> 2) & 1) * half,
                             origin.z + ((slot >> 1) & 1) * half);
            values[slot] = build(child, level - 1);
            if (failed_) return 0;
            // Leaves are one colour each, so a run of 8 leaves is the last 8 colours.
            uniform = uniform && isLeaf(values[slot]) && values[slot] == values[0] &&
                      tree_.colours[mark + slot] == tree_.colours[mark];
        }
        if (uniform && collapse_) {
            tree_.colours.resize(mark + 1);
            return values[0];
        }
        const std::uint32_t base = internLeafOrder(table_, tree_, values);
        if (base == 0) return fail("more than 2^32 entries or leaves; too detailed for the format");
        return branchTo(base);
    }

  private:
    std::uint32_t leaf(std::uint8_t opacity, Colour colour) {
        std::vector<Colour>& c = tree_.colours;
        // Estimate before the array doubles: a large coloured scene must fail politely.
        if (c.size() == c.capacity() && c.size() >= (std::size_t{1} << 20)) {
            if (Status s = checkMemory(c.size() * sizeof(Colour), "octree leaf colours"); !s) {
                fail(s.error().message());
                return 0;
            }
        }
        c.push_back(opacity == 0 ? Colour{} : colour);
        return opacity;
    }

    std::uint32_t fail(const std::string& problem) {
        if (!failed_) problem_ = problem;
        failed_ = true;
        return 0;
    }

    const OctreeSource& source_;
    Octree& tree_;
    OctantTable table_;
    bool collapse_;
    Int3 size_;
    bool failed_ = false;
    std::string problem_;
};

}  // namespace

Result<Octree> buildLeafOrderTree(const OctreeSource& source, const BuildOptions& options,
                                  int depth) {
    Octree tree;
    tree.depth = depth;
    tree.size = source.size();
    tree.layout = AttributeLayout::LeafOrder;
    tree.nodes.assign(8, 0);
    tree.leafCounts.assign(1, 0);  // the root's, set below
    LeafOrderBuilder builder(source, tree, options.collapse);
    const int half = 1 << (depth - 1);
    std::uint32_t root[8];
    for (int slot = 0; slot < 8; ++slot) {
        const Int3 child((slot & 1) * half, ((slot >> 2) & 1) * half, ((slot >> 1) & 1) * half);
        root[slot] = builder.build(child, depth - 1);
        if (builder.failed()) return Error("octree: " + builder.problem());
    }
    const std::uint64_t leaves = octantLeaves(tree, root);
    if (leaves > std::numeric_limits<std::uint32_t>::max()) {
        return Error("octree: more than 2^32 leaves; too detailed for the leaf-order layout");
    }
    for (int i = 0; i < 8; ++i) tree.nodes[i] = root[i];
    tree.leafCounts[0] = static_cast<std::uint32_t>(leaves);
    tree.nodes.shrink_to_fit();
    tree.colours.shrink_to_fit();
    tree.leafCounts.shrink_to_fit();
    return tree;
}

Result<std::vector<std::uint32_t>> computeLeafCounts(const std::vector<std::uint32_t>& nodes) {
    const std::size_t octants = nodes.size() / 8;
    std::vector<std::uint64_t> count(octants, 0);
    std::vector<bool> done(octants, false);
    // Post-order without recursion: an octant is summed once all its children are done.
    std::vector<std::uint32_t> todo{0};
    while (!todo.empty()) {
        const std::uint32_t o = todo.back();
        if (done[o]) {
            todo.pop_back();
            continue;
        }
        bool ready = true;
        for (int i = 0; i < 8; ++i) {
            const std::uint32_t v = nodes[o * std::size_t{8} + i];
            if (!isLeaf(v) && !done[childBase(v) / 8]) {
                todo.push_back(childBase(v) / 8);
                ready = false;
            }
        }
        if (!ready) continue;
        std::uint64_t n = 0;
        for (int i = 0; i < 8; ++i) {
            const std::uint32_t v = nodes[o * std::size_t{8} + i];
            n += isLeaf(v) ? 1 : count[childBase(v) / 8];
        }
        if (n > std::numeric_limits<std::uint32_t>::max()) {
            return Error("octree octant " + std::to_string(o * std::uint64_t{8}) + " has " +
                         std::to_string(n) + " leaves below it, more than the 2^32 - 1 the " +
                         "leaf-order layout indexes");
        }
        count[o] = n;
        done[o] = true;
        todo.pop_back();
    }
    return std::vector<std::uint32_t>(count.begin(), count.end());
}

}  // namespace luxel::octree
