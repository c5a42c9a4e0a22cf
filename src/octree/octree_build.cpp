#include "luxel/octree/octree_build.h"

#include <string>

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

// Recursive bottom-up build: each call returns the entry for one aligned cube, collapsing uniform
// octants into a leaf and interning the rest.
class Builder {
  public:
    Builder(const OctreeSource& source, Octree& tree, bool colours, bool collapse)
        : source_(source),
          tree_(tree),
          table_(tree),
          colours_(colours),
          collapse_(collapse),
          size_(source.size()) {}

    bool failed() const { return failed_; }

    // The entry for the cube [origin, origin + 2^level).
    Entry build(Int3 origin, int level) {
        if (collapse_ && (origin.x >= size_.x || origin.y >= size_.y || origin.z >= size_.z)) {
            return {};
        }
        if (level == 0) {
            Entry e;
            if (origin.x >= size_.x || origin.y >= size_.y || origin.z >= size_.z) return e;
            std::uint8_t opacity = 0;
            source_.voxel(origin, opacity, e.colour);
            e.value = opacity;
            if (opacity == 0 || !colours_) e.colour = Colour{};
            return e;
        }
        if (auto uniform = collapse_ ? source_.uniformBlock(origin, level) : std::nullopt) {
            Entry e{uniform->opacity, uniform->colour};
            if (e.value == 0 || !colours_) e.colour = Colour{};
            return e;
        }
        const int half = 1 << (level - 1);
        std::uint32_t values[8];
        Colour colours[8];
        bool uniform = true;
        for (int slot = 0; slot < 8; ++slot) {
            const Int3 child(origin.x + (slot & 1) * half, origin.y + ((slot >> 2) & 1) * half,
                             origin.z + ((slot >> 1) & 1) * half);
            const Entry e = build(child, level - 1);
            values[slot] = e.value;
            colours[slot] = e.colour;
            uniform = uniform && isLeaf(e.value) && e.value == values[0] && e.colour == colours[0];
        }
        if (uniform && collapse_) return {values[0], colours[0]};
        const std::uint32_t base = table_.intern(values, colours_ ? colours : nullptr);
        if (base == 0) {
            failed_ = true;
            return {};
        }
        return {branchTo(base), Colour{}};
    }

  private:
    const OctreeSource& source_;
    Octree& tree_;
    OctantTable table_;
    bool colours_;
    bool collapse_;
    Int3 size_;
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

}  // namespace

Result<Octree> buildOctree(const OctreeSource& source, const BuildOptions& options) {
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
    Builder builder(source, tree, colours, options.collapse);
    const int half = 1 << (depth - 1);
    for (int slot = 0; slot < 8; ++slot) {
        const Int3 child((slot & 1) * half, ((slot >> 2) & 1) * half, ((slot >> 1) & 1) * half);
        const Entry e = builder.build(child, depth - 1);
        tree.nodes[slot] = e.value;
        if (colours) tree.colours[slot] = e.colour;
    }
    if (builder.failed()) {
        return Error("octree: more than 2^32 entries; the scene is too detailed for the format");
    }
    tree.nodes.shrink_to_fit();
    tree.colours.shrink_to_fit();
    return tree;
}

Result<Octree> buildOctree(const Volume& volume, const BuildOptions& options) {
    return buildOctree(VolumeSource(volume), options);
}

Result<Octree> buildOctree(const voxel::VoxelWorld& world, const BuildOptions& options) {
    return buildOctree(WorldSource(world), options);
}

}  // namespace luxel::octree
