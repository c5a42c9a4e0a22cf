// exportVdb (luxel/octree/octree_vdb.h): the octree's leaves filled into a FOG_VOLUME float grid.
#include <sstream>
#include <string>
#include <unordered_map>

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include "luxel/core/file_io.h"
#include "luxel/core/memory.h"
#include "luxel/octree/octree_validate.h"
#include "luxel/octree/octree_vdb.h"

namespace luxel::octree {
namespace {

// The grid's bytes per leaf node: 8^3 floats, two masks and the node's bookkeeping, and as many
// again for the file's bytes in memory (at most: they are compressed).
constexpr std::uint64_t kGridBytesPerLeafNode = 2 * 2304;

// How many cubes 8 voxels wide the expanded tree under `entry` (2^level wide) does not hold
// uniformly: the grid's leaf nodes, since the grid's nodes are aligned like the tree's cubes.
// Memoised per shared octant and level, so it is linear in the DAG, not in the expanded tree.
std::uint64_t leafNodes(const Octree& tree, std::uint32_t entry, int level,
                        std::unordered_map<std::uint64_t, std::uint64_t>& memo) {
    if (isLeaf(entry) || level < 3) return 0;
    if (level == 3) return 1;
    const std::uint64_t key = std::uint64_t{entry} << 5 | static_cast<std::uint64_t>(level);
    if (auto it = memo.find(key); it != memo.end()) return it->second;
    std::uint64_t n = 0;
    for (int slot = 0; slot < 8; ++slot) {
        n += leafNodes(tree, tree.nodes[childBase(entry) + slot], level - 1, memo);
    }
    memo.emplace(key, n);
    return n;
}

// Fills the leaves under `entry` (a cube 2^level wide at `origin`), clipped to the content box.
void fill(const Octree& tree, std::uint32_t entry, Int3 origin, int level, Int3 extent,
          openvdb::FloatGrid& grid) {
    if (!isLeaf(entry)) {
        const std::uint32_t base = childBase(entry);
        const int half = 1 << (level - 1);
        for (int slot = 0; slot < 8; ++slot) {
            const Int3 child(origin.x + (slot & 1) * half, origin.y + ((slot >> 2) & 1) * half,
                             origin.z + ((slot >> 1) & 1) * half);
            if (child.x < extent.x && child.y < extent.y && child.z < extent.z) {
                fill(tree, tree.nodes[base + slot], child, level - 1, extent, grid);
            }
        }
        return;
    }
    if (entry == 0) return;
    const float value = static_cast<float>(entry) / 255.0f;
    const int side = 1 << level;
    const openvdb::Coord lo(origin.x, origin.y, origin.z);
    const openvdb::Coord hi(std::min(origin.x + side, extent.x) - 1,
                            std::min(origin.y + side, extent.y) - 1,
                            std::min(origin.z + side, extent.z) - 1);
    if (level == 0) {
        grid.tree().setValueOn(lo, value);
    } else {
        // Cubes of the octree are aligned like the grid's nodes: whole nodes become tiles.
        grid.tree().fill(openvdb::CoordBBox(lo, hi), value, /*active=*/true);
    }
}

}  // namespace

Status exportVdb(const Octree& tree, const std::string& path, const VdbExportOptions& options) {
    if (options.grid.empty()) return Error(path + ": the grid name must not be empty");
    if (Status s = validateOctree(tree); !s) return Error(path + ": " + s.error().message());
    std::unordered_map<std::uint64_t, std::uint64_t> memo;
    std::uint64_t nodes = 0;
    for (int slot = 0; slot < 8; ++slot)
        nodes += leafNodes(tree, tree.nodes[slot], tree.depth - 1, memo);
    if (Status s = checkMemory(nodes * kGridBytesPerLeafNode,
                               path + ": a grid of " + std::to_string(nodes) + " leaf nodes");
        !s) {
        return s.error();
    }
    openvdb::initialize();
    std::string bytes;
    try {
        auto grid = openvdb::FloatGrid::create(0.0f);
        grid->setName(options.grid);
        grid->setGridClass(openvdb::GRID_FOG_VOLUME);
        const Int3 extent = tree.extent();
        grid->insertMeta(kVdbContentSizeKey,
                         openvdb::Vec3IMetadata(openvdb::Vec3i(extent.x, extent.y, extent.z)));
        const int half = 1 << (tree.depth - 1);
        for (int slot = 0; slot < 8; ++slot) {
            const Int3 child((slot & 1) * half, ((slot >> 2) & 1) * half, ((slot >> 1) & 1) * half);
            if (child.x < extent.x && child.y < extent.y && child.z < extent.z) {
                fill(tree, tree.nodes[slot], child, tree.depth - 1, extent, *grid);
            }
        }
        grid->tree().prune();
        std::ostringstream out(std::ios_base::out | std::ios_base::binary);
        openvdb::io::Stream(out).write(openvdb::GridCPtrVec{grid});
        bytes = std::move(out).str();
    } catch (const std::exception& e) {
        return Error(path + ": cannot make the OpenVDB grid: " + e.what());
    }
    return writeFileAtomically(path, bytes, "vdb");
}

}  // namespace luxel::octree
