// exportVdb (luxel/octree/octree_vdb.h): the octree's leaves filled into a FOG_VOLUME float grid.
#include <sstream>
#include <string>

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include "luxel/core/file_io.h"
#include "luxel/core/memory.h"
#include "luxel/octree/octree_validate.h"
#include "luxel/octree/octree_vdb.h"

namespace luxel::octree {
namespace {

// Bound on the grid's bytes per octant of the expanded tree: each leaf node (8^3 floats and
// masks, 2.2 KiB) holds a cube that is not uniform, which is an octant of the expanded tree;
// the file's bytes in memory (compressed) are at most as many again.
constexpr std::uint64_t kGridBytesPerOctant = 4608;

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
    const OctreeStats stats = measure(tree);
    if (Status s =
            checkMemory(stats.expandedOctants * kGridBytesPerOctant,
                        path + ": a grid of " + std::to_string(stats.expandedOctants) + " octants");
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
