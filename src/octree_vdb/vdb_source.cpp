#include "octree_vdb/vdb_source.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace luxel::octree {
namespace {

using openvdb::Coord;
using openvdb::CoordBBox;
using Tree = openvdb::FloatTree;

// Side of a tile stored at tree depth d (0 = root; -1 = outside the root's table, background in
// aligned cubes of the root's children): the side of the children of the node at depth d.
constexpr int kLeafDepth = static_cast<int>(Tree::DEPTH) - 1;
constexpr int kTileSides[] = {
    static_cast<int>(Tree::RootNodeType::ChildNodeType::DIM),
    static_cast<int>(Tree::RootNodeType::ChildNodeType::ChildNodeType::DIM),
    static_cast<int>(Tree::LeafNodeType::DIM)};
static_assert(kLeafDepth == 3, "the tile sides above are those of the standard 5-4-3 FloatTree");

int tileSide(int depth) {
    return kTileSides[std::max(depth, 0)];
}

}  // namespace

std::uint8_t VdbQuantiser::operator()(float v) const {
    if (levelSet) return v < 0 ? 255 : 0;
    if (!(v > 0)) return 0;  // also NaN
    const double t = std::min(static_cast<double>(v), static_cast<double>(max)) / max;
    return static_cast<std::uint8_t>(std::lround(255.0 * t));
}

VdbSource::VdbSource(const openvdb::FloatGrid& grid, openvdb::Coord origin, Int3 size,
                     VdbQuantiser quantise)
    : origin_(origin), size_(size), quantise_(quantise), accessors_(grid.getConstAccessor()) {}

void VdbSource::voxel(Int3 cell, std::uint8_t& opacity, Colour& colour) const {
    opacity = quantise_(accessor().getValue(origin_.offsetBy(cell.x, cell.y, cell.z)));
    colour = Colour{};
}

std::optional<OctreeSource::Uniform> VdbSource::uniformBlock(Int3 origin, int level) const {
    // Cubes of 2 or 8 voxels are cheaper to read than to reason about.
    if (level < 2) return std::nullopt;
    const int side = 1 << level;
    Int3 last;
    bool clipped = false;
    for (int a = 0; a < 3; ++a) {
        last[a] = std::min(origin[a] + side, size_[a]) - 1;
        clipped = clipped || origin[a] + side > size_[a];
    }
    if (last.x < origin.x || last.y < origin.y || last.z < origin.z) return Uniform{};
    const CoordBBox box(origin_.offsetBy(origin.x, origin.y, origin.z),
                        origin_.offsetBy(last.x, last.y, last.z));
    const std::optional<std::uint8_t> opacity = uniformOpacity(box);
    // Cells outside the content box are empty, so a clipped cube is uniform only when empty.
    if (!opacity || (clipped && *opacity != 0)) return std::nullopt;
    return Uniform{*opacity, Colour{}};
}

std::optional<std::uint8_t> VdbSource::uniformOpacity(const CoordBBox& box) const {
    std::optional<std::uint8_t> value;
    auto same = [&](float v) {
        const std::uint8_t q = quantise_(v);
        if (!value) value = q;
        return *value == q;
    };
    // Visit the box one tree node or tile at a time: take the node holding its lowest corner,
    // then queue the (up to 3) boxes of the rest. A work list, not recursion: a box may cross
    // thousands of nodes.
    std::vector<CoordBBox> work{box};
    while (!work.empty()) {
        const CoordBBox b = work.back();
        work.pop_back();
        const Coord p = b.min();
        CoordBBox region;
        const int depth = accessor().getValueDepth(p);
        if (depth == kLeafDepth) {
            const Tree::LeafNodeType* leaf = accessor().probeConstLeaf(p);
            region = leaf->getNodeBoundingBox();
            const Coord end = Coord::minComponent(region.max(), b.max());
            for (int x = p.x(); x <= end.x(); ++x) {
                for (int y = p.y(); y <= end.y(); ++y) {
                    for (int z = p.z(); z <= end.z(); ++z) {
                        if (!same(leaf->getValue(Coord(x, y, z)))) return std::nullopt;
                    }
                }
            }
        } else {
            const int s = tileSide(depth);
            region = CoordBBox::createCube(
                Coord(p.x() & ~(s - 1), p.y() & ~(s - 1), p.z() & ~(s - 1)), s);
            if (!same(accessor().getValue(p))) return std::nullopt;
        }
        const Coord& r = region.max();
        const Coord& e = b.max();
        if (r.x() < e.x()) work.emplace_back(Coord(r.x() + 1, p.y(), p.z()), e);
        const int xEnd = std::min(r.x(), e.x());
        if (r.y() < e.y())
            work.emplace_back(Coord(p.x(), r.y() + 1, p.z()), Coord(xEnd, e.y(), e.z()));
        const int yEnd = std::min(r.y(), e.y());
        if (r.z() < e.z())
            work.emplace_back(Coord(p.x(), p.y(), r.z() + 1), Coord(xEnd, yEnd, e.z()));
    }
    return value;
}

}  // namespace luxel::octree
