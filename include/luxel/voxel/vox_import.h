// MagicaVoxel .vox files: a bounds-checked reader and a writer. Format: "VOX " magic, version,
// then RIFF-style chunks (id, content size, children size); see ephtracy/voxel-model,
// MagicaVoxel-file-format-vox.txt. MagicaVoxel is z-up: vox (x, y, z) is luxel (x, z, y).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Files larger than this are refused before reading.
inline constexpr std::uint64_t kMaxVoxFileBytes = std::uint64_t{256} << 20;

// Reads a .vox file (version 150 or 200). Every model (SIZE + XYZI pair) is placed side by side
// along luxel x in file order, each at z = 0, y = 0; the world is as wide as their sum and as
// tall/deep as the largest. Scene-graph chunks (nTRN, nGRP, nSHP), materials and any other
// chunks are skipped. Palette alpha is ignored: every listed voxel is a plain block (alpha 255;
// alpha 1..254 would select a face texture, texture_set.h). Each model side must be in 1..256 (XYZI
// coordinates are bytes). Voxels with colour index 0 (not a valid index) are skipped. Without an
// RGBA chunk the default MagicaVoxel palette is used. Every bad input is an Error like "model.vox:
// byte 52: XYZI chunk claims 1000000 voxels but holds 40 bytes".
Result<VoxelWorld> loadVox(const std::string& path, int chunkSize = 32);
// The same from bytes in memory; `name` is used in messages.
Result<VoxelWorld> parseVox(std::span<const std::uint8_t> bytes, const std::string& name,
                            int chunkSize = 32);

// Encodes the world as one model (version 150: SIZE, XYZI, RGBA). Each side must be at most 256
// (the format stores coordinates as bytes). The palette holds the distinct colours (RGBA) of the
// solid voxels; when there are more than 255, the 255 most frequent are kept and every other
// colour is written as the nearest kept one (squared RGBA distance).
Result<std::vector<std::uint8_t>> encodeVox(const VoxelWorld& world);
Status saveVox(const VoxelWorld& world, const std::string& path);

// The default MagicaVoxel palette, indexed by colour index (entry 0 is unused).
const std::array<Voxel, 256>& defaultVoxPalette();

}  // namespace luxel::voxel
