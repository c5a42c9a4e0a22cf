// OpenVDB files as octrees and back (docs/algorithms/sparse-voxel-octree.md §6). Lives in its own
// library, luxel_octree_vdb, so that only what reads or writes .vdb files links OpenVDB; this
// header includes no OpenVDB header.
//
// Import: one float grid of the file; the box of its active voxels and tiles becomes the content
// box (its lowest corner is cell 0), and each value becomes an 8-bit opacity:
// - fog volumes and grids of any other class: round(255 * clamp(v, 0, max) / max);
// - level sets: 255 inside (v < 0), 0 outside; `max` is not used.
// Values are read whether the voxel is active or not (a level set's interior is inactive).
// Export: a FOG_VOLUME float grid of opacity / 255 in index space (voxel (i, j, k) of the
// octree is voxel (i, j, k) of the grid), pruned; the content size is kept in the grid's
// metadata so that octree -> vdb -> octree gives back the same tree.
#pragma once

#include <string>

#include "luxel/core/error.h"
#include "luxel/octree/octree.h"

namespace luxel::octree {

struct VdbImportOptions {
    std::string grid;  // the float grid to read; empty: the first float grid of the file
    float max = 0;     // the value that maps to opacity 255; 0: 1.0 (fog volumes)
};

struct VdbExportOptions {
    std::string grid = "density";  // the grid's name
};

// The name of the grid metadata entry (a vec3i) export writes the content size to.
inline constexpr const char* kVdbContentSizeKey = "luxel_content_size";

// Every OpenVDB failure (missing file, not a .vdb, no such grid) is an Error naming the file.
Result<Octree> importVdb(const std::string& path, const VdbImportOptions& options = {});

// Written through a temporary file and a rename, like writeOctreeFile.
Status exportVdb(const Octree& tree, const std::string& path, const VdbExportOptions& options = {});

}  // namespace luxel::octree
