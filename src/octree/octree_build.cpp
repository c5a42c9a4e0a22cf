#include "luxel/octree/octree_build.h"

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "octant_table.h"
#include "octree/leaf_order.h"

namespace luxel::octree {

int depthFor(Int3 size) {
    const int side = std::max({size.x, size.y, size.z, 2});
    int depth = 1;
    while ((1 << depth) < side) ++depth;
    return depth;
}

namespace {

struct Entry {
    std::uint32_t value = 0;
    Colour colour;
};

bool outside(Int3 origin, Int3 size) {
    return origin.x >= size.x || origin.y >= size.y || origin.z >= size.z;
}

Int3 childOrigin(Int3 origin, int slot, int half) {
    return {origin.x + (slot & 1) * half, origin.y + ((slot >> 2) & 1) * half,
            origin.z + ((slot >> 1) & 1) * half};
}

// What one octant of 8 child entries becomes: one leaf when all 8 are the same leaf (the
// collapse), else the interned octant. `failed` is set when the array would outgrow the format.
Entry octantEntry(const std::uint32_t* values, const Colour* colours, bool collapse,
                  bool withColours, OctantTable& table, bool& failed) {
    bool uniform = true;
    for (int slot = 0; slot < 8; ++slot) {
        uniform = uniform && isLeaf(values[slot]) && values[slot] == values[0] &&
                  colours[slot] == colours[0];
    }
    if (uniform && collapse) return {values[0], colours[0]};
    const std::uint32_t base = table.intern(values, withColours ? colours : nullptr);
    if (base == 0) {
        failed = true;
        return {};
    }
    return {branchTo(base), Colour{}};
}

// Recursive bottom-up build of one aligned cube into its own array: collapsing uniform octants
// into a leaf and interning the rest. `Source` is a final class where the caller knows it, so the
// per-voxel reads are direct calls.
template <typename Source>
class SubtreeBuilder {
  public:
    SubtreeBuilder(const Source& source, Octree& tree, bool colours, bool collapse)
        : source_(source),
          table_(tree),
          colours_(colours),
          collapse_(collapse),
          size_(source.size()) {}

    bool failed() const { return failed_; }

    // The entry for the cube [origin, origin + 2^level).
    Entry build(Int3 origin, int level) {
        if (collapse_ && outside(origin, size_)) return {};
        if (level == 0) return voxel(origin);
        if (auto uniform = collapse_ ? source_.uniformBlock(origin, level) : std::nullopt) {
            Entry e{uniform->opacity, uniform->colour};
            if (e.value == 0 || !colours_) e.colour = Colour{};
            return e;
        }
        std::uint32_t values[8];
        Colour colours[8];
        const int half = 1 << (level - 1);
        for (int slot = 0; slot < 8; ++slot) {
            // The voxel level inline: most calls of a dense region end there.
            const Entry e = level == 1 ? voxel(childOrigin(origin, slot, half))
                                       : build(childOrigin(origin, slot, half), level - 1);
            values[slot] = e.value;
            colours[slot] = e.colour;
        }
        return octantEntry(values, colours, collapse_, colours_, table_, failed_);
    }

  private:
    Entry voxel(Int3 cell) const {
        Entry e;
        if (outside(cell, size_)) return e;
        std::uint8_t opacity = 0;
        source_.voxel(cell, opacity, e.colour);
        e.value = opacity;
        if (opacity == 0 || !colours_) e.colour = Colour{};
        return e;
    }

    const Source& source_;
    OctantTable table_;
    bool colours_;
    bool collapse_;
    Int3 size_;
    bool failed_ = false;
};

// One task's result: a subtree built into its own array (entries 0-7 unused, so local bases
// start at 8 as in the final array) and the entry standing for the whole cube.
struct Subtree {
    Octree local;
    Entry root;
    bool failed = false;
};

// The levels above the tasks, in the order the sequential recursion finishes them (children
// before parents, slot by slot), so replaying them gives the sequential recursion's array.
struct PlanNode {
    enum class Kind : std::uint8_t { Leaf, Task, Branch };
    Kind kind = Kind::Leaf;
    Entry entry;                     // a leaf's entry; any node's entry once merged
    std::uint32_t children[8] = {};  // a branch's children (plan indices)
};

// Builds the tree in parallel and gives the array the sequential recursion gives, for any
// thread count: the cubes a few levels below the root are built as independent tasks into
// per-task tables, then merged strictly in the recursion's order. Why that is exact: within a
// task, a local table appends each distinct octant at its first occurrence in the task's
// depth-first order, which is the recursion's order restricted to the task; re-interning the
// local octants in that order into the global table appends exactly those not seen in earlier
// tasks, in the order the recursion would have appended them.
template <typename Source>
class ParallelBuilder {
  public:
    ParallelBuilder(const Source& source, Octree& tree, bool colours, bool collapse)
        : source_(source),
          tree_(tree),
          table_(tree),
          colours_(colours),
          collapse_(collapse),
          size_(source.size()) {}

    // Builds the root octant's 8 entries; false when the array would outgrow the format.
    bool run() {
        const int top = tree_.depth - 1;  // the level of the root's entries
        // About 8^3 tasks: enough to balance any thread count, few enough to merge cheaply.
        splitLevel_ = std::max(0, top - 2);
        const int half = 1 << top;
        std::uint32_t roots[8];
        for (int slot = 0; slot < 8; ++slot) roots[slot] = plan(childOrigin({}, slot, half), top);
        runTasks();
        if (failed_) return false;
        for (int slot = 0; slot < 8; ++slot) {
            tree_.nodes[slot] = plan_[roots[slot]].entry.value;
            if (colours_) tree_.colours[slot] = plan_[roots[slot]].entry.colour;
        }
        return true;
    }

  private:
    // Plans the cube's levels above the tasks; returns its plan index.
    std::uint32_t plan(Int3 origin, int level) {
        PlanNode node;
        if (level <= splitLevel_) {
            node.kind = PlanNode::Kind::Task;
            tasks_.push_back(origin);
        } else if (collapse_ && outside(origin, size_)) {
            node.kind = PlanNode::Kind::Leaf;
        } else if (auto uniform = collapse_ ? source_.uniformBlock(origin, level) : std::nullopt) {
            node.kind = PlanNode::Kind::Leaf;
            node.entry = {uniform->opacity, uniform->colour};
            if (node.entry.value == 0 || !colours_) node.entry.colour = Colour{};
        } else {
            node.kind = PlanNode::Kind::Branch;
            const int half = 1 << (level - 1);
            for (int slot = 0; slot < 8; ++slot) {
                node.children[slot] = plan(childOrigin(origin, slot, half), level - 1);
            }
        }
        plan_.push_back(node);
        return static_cast<std::uint32_t>(plan_.size() - 1);
    }

    std::unique_ptr<Subtree> buildTask(std::size_t task) const {
        auto out = std::make_unique<Subtree>();
        out->local.depth = tree_.depth;
        out->local.nodes.assign(8, 0);
        if (colours_) out->local.colours.assign(8, Colour{});
        SubtreeBuilder<Source> builder(source_, out->local, colours_, collapse_);
        out->root = builder.build(tasks_[task], splitLevel_);
        out->failed = builder.failed();
        return out;
    }

    // Re-interns a task's octants into the tree in their local order, then finishes the plan's
    // branches up to the next task. The table is far larger than the cache, so the slot of the
    // octant kAhead places on is prefetched while this one is interned.
    void merge(Subtree& task) {
        failed_ = failed_ || task.failed;
        const Octree& local = task.local;
        const std::size_t octants = local.nodes.size() / 8;
        std::vector<std::uint32_t> globalBase(octants, 0);
        // The octant's entries with branches mapped to the tree; false while a child is not
        // merged yet (children precede parents: the local table appends in post-order).
        auto mapped = [&](std::size_t o, std::size_t merged, std::uint32_t* values) {
            for (int slot = 0; slot < 8; ++slot) {
                const std::uint32_t v = local.nodes[o * 8 + slot];
                if (isLeaf(v)) {
                    values[slot] = v;
                    continue;
                }
                const std::size_t child = childBase(v) / 8;
                if (child >= merged) return false;
                values[slot] = branchTo(globalBase[child]);
            }
            return true;
        };
        auto coloursOf = [&](std::size_t o) { return colours_ ? &local.colours[o * 8] : nullptr; };
        constexpr std::size_t kAhead = 16;
        std::uint64_t ahead[kAhead];
        bool hashed[kAhead] = {};
        std::uint32_t values[8];
        auto prepare = [&](std::size_t p, std::size_t merged) {
            hashed[p % kAhead] = p < octants && mapped(p, merged, values);
            if (hashed[p % kAhead]) {
                ahead[p % kAhead] = table_.hash(values, coloursOf(p));
                table_.prefetch(ahead[p % kAhead]);
            }
        };
        for (std::size_t p = 1; p <= kAhead; ++p) prepare(p, 1);
        for (std::size_t o = 1; o < octants && !failed_; ++o) {
            mapped(o, o, values);
            const std::uint64_t h =
                hashed[o % kAhead] ? ahead[o % kAhead] : table_.hash(values, coloursOf(o));
            globalBase[o] = table_.intern(values, coloursOf(o), h);
            failed_ = globalBase[o] == 0;
            prepare(o + kAhead, o + 1);
        }
        Entry root = task.root;
        if (!isLeaf(root.value) && !failed_) {
            root.value = branchTo(globalBase[childBase(root.value) / 8]);
        }
        while (cursor_ < plan_.size() && plan_[cursor_].kind != PlanNode::Kind::Task) ++cursor_;
        plan_[cursor_++].entry = root;
        finishBranches();
    }

    // Interns the plan's branches until the next task (their children are all known by then).
    void finishBranches() {
        for (; cursor_ < plan_.size() && plan_[cursor_].kind != PlanNode::Kind::Task; ++cursor_) {
            PlanNode& node = plan_[cursor_];
            if (node.kind != PlanNode::Kind::Branch || failed_) continue;
            std::uint32_t values[8];
            Colour colours[8];
            for (int slot = 0; slot < 8; ++slot) {
                values[slot] = plan_[node.children[slot]].entry.value;
                colours[slot] = plan_[node.children[slot]].entry.colour;
            }
            node.entry = octantEntry(values, colours, collapse_, colours_, table_, failed_);
        }
    }

    void runTasks() {
        finishBranches();  // the plan may start with leaves only
        std::size_t next = 0;
        std::atomic<bool> stop{false};
        // A few subtrees in flight per thread: they wait in memory until merged in order.
        const auto tokens = static_cast<std::size_t>(4 * tbb::this_task_arena::max_concurrency());
        tbb::parallel_pipeline(
            tokens,
            tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                                [&](tbb::flow_control& fc) -> std::size_t {
                                                    if (next == tasks_.size() || stop.load()) {
                                                        fc.stop();
                                                        return 0;
                                                    }
                                                    return next++;
                                                }) &
                tbb::make_filter<std::size_t, std::shared_ptr<Subtree>>(
                    tbb::filter_mode::parallel,
                    [&](std::size_t task) { return std::shared_ptr<Subtree>(buildTask(task)); }) &
                tbb::make_filter<std::shared_ptr<Subtree>, void>(
                    tbb::filter_mode::serial_in_order, [&](std::shared_ptr<Subtree> task) {
                        merge(*task);
                        if (failed_) stop = true;
                    }));
    }

    const Source& source_;
    Octree& tree_;
    OctantTable table_;
    bool colours_;
    bool collapse_;
    Int3 size_;
    int splitLevel_ = 0;
    std::vector<PlanNode> plan_;
    std::vector<Int3> tasks_;  // task cubes (at splitLevel_) in the recursion's order
    std::size_t cursor_ = 0;   // the first plan node not yet finished
    bool failed_ = false;
};

class VolumeSource final : public OctreeSource {
  public:
    explicit VolumeSource(const Volume& volume) : volume_(volume) {}
    Int3 size() const override { return volume_.size(); }
    bool hasColours() const override { return volume_.hasColours(); }
    void voxel(Int3 c, std::uint8_t& opacity, Colour& colour) const override {
        const std::size_t i = volume_.index(c.x, c.y, c.z);
        opacity = volume_.opacities()[i];
        colour = volume_.colour(c.x, c.y, c.z);
    }

  private:
    const Volume& volume_;
};

// Voxel worlds answer "empty" from their brick masks and chunk counts.
class WorldSource final : public OctreeSource {
  public:
    explicit WorldSource(const voxel::VoxelWorld& world) : world_(world) {
        while ((1 << chunkShift_) < world.chunkSize()) ++chunkShift_;
    }
    Int3 size() const override { return world_.size(); }
    bool hasColours() const override { return true; }
    AttributeLayout preferredLayout() const override { return AttributeLayout::LeafOrder; }
    void voxel(Int3 c, std::uint8_t& opacity, Colour& colour) const override {
        const voxel::Voxel v = world_.get(c.x, c.y, c.z);
        opacity = v.solid() ? 255 : 0;
        colour = v;
    }
    std::optional<Uniform> uniformBlock(Int3 origin, int level) const override {
        constexpr int brickShift = voxel::VoxelWorld::kBrickShift;
        if (level == brickShift) {
            if (world_.brickMask(origin.x >> brickShift, origin.y >> brickShift,
                                 origin.z >> brickShift) == 0) {
                return Uniform{};
            }
        } else if (level == chunkShift_) {
            if (world_.chunkSolidCount(origin.x >> chunkShift_, origin.y >> chunkShift_,
                                       origin.z >> chunkShift_) == 0) {
                return Uniform{};
            }
        }
        return std::nullopt;
    }

  private:
    const voxel::VoxelWorld& world_;
    int chunkShift_ = 0;
};

// Sources are read from several threads at once (their methods are const).
template <typename Source>
Result<Octree> buildFrom(const Source& source, const BuildOptions& options) {
    const Int3 size = source.size();
    if (size.x < 1 || size.y < 1 || size.z < 1) return Error("octree source has an empty size");
    const int depth = depthFor(size);
    if (depth > kMaxDepth) {
        return Error("octree source " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                     "x" + std::to_string(size.z) + " needs depth " + std::to_string(depth) +
                     ", more than the supported " + std::to_string(kMaxDepth));
    }
    const AttributeLayout layout = options.layout.value_or(source.preferredLayout());
    const bool colours = options.colours && source.hasColours() && layout != AttributeLayout::None;
    if (colours && layout == AttributeLayout::LeafOrder) {
        return buildLeafOrderTree(source, options, depth);
    }
    Octree tree;
    tree.depth = depth;
    tree.size = size;
    tree.nodes.assign(8, 0);
    if (colours) tree.colours.assign(8, Colour{});
    ParallelBuilder<Source> builder(source, tree, colours, options.collapse);
    if (!builder.run()) {
        return Error("octree: more than 2^32 entries; the scene is too detailed for the format");
    }
    tree.nodes.shrink_to_fit();
    tree.colours.shrink_to_fit();
    return tree;
}

}  // namespace

Result<Octree> buildOctree(const OctreeSource& source, const BuildOptions& options) {
    return buildFrom(source, options);
}

Result<Octree> buildOctree(const Volume& volume, const BuildOptions& options) {
    return buildFrom(VolumeSource(volume), options);
}

Result<Octree> buildOctree(const voxel::VoxelWorld& world, const BuildOptions& options) {
    return buildFrom(WorldSource(world), options);
}

}  // namespace luxel::octree
