// The octree container file (.lxo), little-endian:
//   offset  0  8 bytes  magic "LXOCTREE"
//           8  u32      version (1)
//          12  u32      depth (1..kMaxDepth)
//          16  3 x u32  content size x, y, z (Octree::size; 0 0 0 = the whole cube)
//          28  u32      flags: bit 0 = colours follow the entries; other bits must be 0
//          32  u64      entry count n
//          40  n x u32  the entries (octree.h)
//              n x 4    RGBA colours, one per entry, when flag bit 0 is set
// Reading checks the header against the file size before allocating and validates the tree
// (octree_validate.h), so a hostile file gives an error, never a crash or a huge allocation.
#pragma once

#include <string>
#include <string_view>

#include "luxel/core/error.h"
#include "luxel/octree/octree.h"

namespace luxel::octree {

inline constexpr std::string_view kOctreeMagic = "LXOCTREE";
inline constexpr std::uint32_t kOctreeFileVersion = 1;
inline constexpr std::size_t kOctreeHeaderBytes = 40;

std::string serializeOctree(const Octree& tree);
// `name` labels errors ("terrain.lxo: ...").
Result<Octree> parseOctree(std::string_view bytes, const std::string& name);

Result<Octree> readOctreeFile(const std::string& path);
// Written through a temporary file and a rename (luxel/core/file_io.h).
Status writeOctreeFile(const std::string& path, const Octree& tree);

}  // namespace luxel::octree
