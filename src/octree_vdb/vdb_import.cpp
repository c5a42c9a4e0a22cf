// importVdb (luxel/octree/octree_vdb.h): choose a float grid, size and memory checks, then the
// octree builder over a VdbSource.
#include <cmath>
#include <cstdint>
#include <string>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "luxel/core/memory.h"
#include "luxel/octree/octree_vdb.h"
#include "octree_vdb/vdb_source.h"

namespace luxel::octree {
namespace {

// Bound on the octree's bytes per voxel of the grid's leaf nodes: a leaf node (8^3) not aligned
// with the octree's cubes meets at most 5^3 bottom octants (2^3 voxels, 32 bytes each): 7.8 bytes
// per voxel; the levels above add under 1/7, the sharing table 1/4 (4-byte slots, at most half
// full), and the array's growth by doubling up to 2x. Uniform tiles add only their faces.
constexpr std::uint64_t kOctreeBytesPerLeafVoxel = 20;

std::string describe(const openvdb::CoordBBox& box) {
    const auto c = [](const openvdb::Coord& p) {
        return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
               std::to_string(p.z()) + ")";
    };
    return c(box.min()) + " .. " + c(box.max());
}

// "density (float), v (vec3s)": what the file holds, for "no such grid" errors.
std::string listGrids(const openvdb::GridPtrVec& grids) {
    std::string list;
    for (const auto& g : grids) {
        list += (list.empty() ? "" : ", ") + g->getName() + " (" + g->valueType() + ")";
    }
    return list.empty() ? "no grids" : list;
}

// The file's float grid chosen by `name` (empty: the first), read whole.
Result<openvdb::FloatGrid::Ptr> readFloatGrid(const std::string& path, const std::string& name) {
    openvdb::io::File file(path);
    file.open(/*delayLoad=*/false);
    const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();
    openvdb::GridBase::ConstPtr chosen;
    for (const auto& g : *grids) {
        if (name.empty() ? g->isType<openvdb::FloatGrid>() : g->getName() == name) {
            chosen = g;
            break;
        }
    }
    if (!chosen) {
        return Error(path + ": " +
                     (name.empty() ? "no float grid" : "no grid named '" + name + "'") +
                     " (the file holds " + listGrids(*grids) + ")");
    }
    if (!chosen->isType<openvdb::FloatGrid>()) {
        return Error(path + ": grid '" + name + "' holds " + chosen->valueType() +
                     " values; luxel reads float grids");
    }
    // Files written by OpenVDB record the grid's size in memory: refuse before reading it.
    if (const auto bytes = chosen->getMetadata<openvdb::Int64Metadata>("file_mem_bytes")) {
        if (Status s =
                checkMemory(static_cast<std::uint64_t>(std::max<std::int64_t>(bytes->value(), 0)),
                            path + ": grid '" + chosen->getName() + "'");
            !s) {
            return s.error();
        }
    }
    auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(chosen->getName()));
    file.close();
    if (!grid) return Error(path + ": cannot read grid '" + chosen->getName() + "'");
    return grid;
}

// The content box: the active box, or [0, size) for a grid luxel wrote (its metadata holds the
// size) as long as the active box lies inside it, so that empty borders survive a round trip.
openvdb::CoordBBox contentBox(const openvdb::FloatGrid& grid) {
    const openvdb::CoordBBox active = grid.evalActiveVoxelBoundingBox();
    const auto size = grid.getMetadata<openvdb::Vec3IMetadata>(kVdbContentSizeKey);
    if (!size) return active;
    const openvdb::Vec3i s = size->value();
    const int limit = 1 << kMaxDepth;
    if (s.x() < 1 || s.y() < 1 || s.z() < 1 || s.x() > limit || s.y() > limit || s.z() > limit) {
        return active;
    }
    const openvdb::CoordBBox box(openvdb::Coord(0),
                                 openvdb::Coord(s.x() - 1, s.y() - 1, s.z() - 1));
    return active.empty() || box.isInside(active) ? box : active;
}

Result<Octree> importGrid(const std::string& path, const openvdb::FloatGrid& grid,
                          const VdbImportOptions& options) {
    const std::string name = "grid '" + grid.getName() + "'";
    const openvdb::CoordBBox box = contentBox(grid);
    if (box.empty()) return Error(path + ": " + name + " has no active voxels");
    Int3 size;
    for (int a = 0; a < 3; ++a) {
        const std::int64_t side = std::int64_t{box.max()[a]} - box.min()[a] + 1;
        if (side > (std::int64_t{1} << kMaxDepth)) {
            return Error(path + ": " + name + " spans " + std::to_string(side) + " voxels along " +
                         "xyz"[a] + " (active box " + describe(box) + "), more than the " +
                         std::to_string(1 << kMaxDepth) + " (2^" + std::to_string(kMaxDepth) +
                         ") an octree holds");
        }
        size[a] = static_cast<int>(side);
    }
    const std::uint64_t leafVoxels =
        grid.tree().leafCount() * openvdb::FloatTree::LeafNodeType::SIZE;
    if (Status s = checkMemory(leafVoxels * kOctreeBytesPerLeafVoxel,
                               path + ": the octree of " + name + " (" +
                                   std::to_string(grid.tree().leafCount()) + " leaf nodes)");
        !s) {
        return s.error();
    }
    VdbQuantiser quantise;
    quantise.levelSet = grid.getGridClass() == openvdb::GRID_LEVEL_SET;
    quantise.max = options.max > 0 ? options.max : 1.0f;
    auto tree = buildOctree(VdbSource(grid, box.min(), size, quantise), {.colours = false});
    if (!tree) return Error(path + ": " + tree.error().message());
    return tree;
}

}  // namespace

Result<Octree> importVdb(const std::string& path, const VdbImportOptions& options) {
    if (!(options.max >= 0) || !std::isfinite(options.max)) {
        return Error(path + ": max must be a positive number, got " + std::to_string(options.max));
    }
    openvdb::initialize();
    try {
        auto grid = readFloatGrid(path, options.grid);
        if (!grid) return grid.error();
        return importGrid(path, **grid, options);
    } catch (const std::exception& e) {
        // openvdb::Exception derives from std::exception; its what() names the kind.
        return Error(path + ": cannot read OpenVDB file: " + e.what());
    }
}

}  // namespace luxel::octree
