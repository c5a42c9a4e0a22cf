// The octree container file (.lxo), little-endian. Version 2 (written):
//   offset  0  8 bytes  magic "LXOCTREE"
//           8  u32      version (2)
//          12  u32      depth (1..kMaxDepth)
//          16  3 x u32  content size x, y, z (Octree::size; 0 0 0 = the whole cube)
//          28  u32      attribute layout: 0 none, 1 per-entry, 2 leaf-order (octree.h)
//          32  u64      entry count n
//          40  u64      colour count m (0; n for per-entry; the root's leaf count for leaf-order)
//          48  n x u32  the entries (octree.h)
//              n/8 x u32  leaf-order only: the leaf count of each octant
//              m x 4    RGBA colours
// Version 1 (still read): a 40-byte header with flags at 28 (bit 0 = one colour per entry
// follows the entries) and no colour count.
// Reading checks the header against the file size before allocating and validates the tree
// (octree_validate.h), so a hostile file gives an error, never a crash or a huge allocation.
#pragma once

#include <string>
#include <string_view>

#include "luxel/core/error.h"
#include "luxel/octree/octree.h"

namespace luxel::octree {

inline constexpr std::string_view kOctreeMagic = "LXOCTREE";
inline constexpr std::uint32_t kOctreeFileVersion = 2;
inline constexpr std::size_t kOctreeHeaderBytes = 48;
inline constexpr std::size_t kOctreeHeaderBytesV1 = 40;

std::string serializeOctree(const Octree& tree);
// `name` labels errors ("terrain.lxo: ...").
Result<Octree> parseOctree(std::string_view bytes, const std::string& name);

Result<Octree> readOctreeFile(const std::string& path);
// Written through a temporary file and a rename (luxel/core/file_io.h).
Status writeOctreeFile(const std::string& path, const Octree& tree);

}  // namespace luxel::octree
