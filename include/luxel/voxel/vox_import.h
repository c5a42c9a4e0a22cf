// MagicaVoxel .vox files: a bounds-checked reader and a writer. Format: "VOX " magic, version,
// then RIFF-style chunks (id, content size, children size); see ephtracy/voxel-model,
// MagicaVoxel-file-format-vox.txt and MagicaVoxel-file-format-vox-extension.txt. MagicaVoxel is
// z-up: vox (x, y, z) is luxel (x, z, y). What of a file is used: docs/scene-format-voxel.md.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/voxel/material.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Files larger than this are refused before reading.
inline constexpr std::uint64_t kMaxVoxFileBytes = std::uint64_t{256} << 20;
// Each side of one .vox model (XYZI coordinates are bytes).
inline constexpr int kMaxVoxModelSide = 256;

struct VoxOptions {
    int chunkSize = 32;
    // The animation frame: transform keyframes (nTRN _f) and model keyframes (nSHP _f) in effect
    // are the last ones at or before it.
    int frame = 0;
    // False: every voxel is a plain block (alpha 255) and VoxImport::materials stays empty.
    bool materials = true;
    // Largest world to build, in bytes (VoxelWorld::bytesFor); 0: as much as the machine has.
    std::uint64_t maxWorldBytes = 0;
};

// A .vox file read into a world.
struct VoxImport {
    VoxelWorld world;
    // The materials of the colours that have one (MATL, palette alpha below 255): a voxel of such
    // a colour has alpha alphaForSlot(i) (texture_set.h), i indexing this list; other voxels are
    // plain blocks (alpha 255). Names are "vox N", N a colour index.
    std::vector<Material> materials;
    // What was not applied or only approximated, one line each, starting with the file name:
    // "m.vox: MATL 37: _media approximated as diffuse", "m.vox: chunk rCAM (cameras) ignored".
    std::vector<std::string> warnings;
    int frameCount = 1;   // 1 + the last keyframe index in the file
    int modelCount = 0;   // SIZE/XYZI models in the file
    int placedCount = 0;  // model placements drawn at the frame
    // The vox position (x, y, z; z up) of luxel voxel (0, 0, 0).
    std::array<std::int64_t, 3> voxOrigin{0, 0, 0};
};

// Reads a .vox file (version 150 or 200). With a scene graph (nTRN, nGRP, nSHP; hidden nodes and
// layers left out) every model lands where MagicaVoxel shows it, and the world spans the placed
// models; without one, a single model sits at the origin and several are laid side by side along
// x (with a warning). Every bad input is an Error like "model.vox: byte 52: XYZI chunk claims
// 1000000 voxels but holds 40 bytes"; a placement too large for a world names its size and the
// memory it would need.
Result<VoxImport> readVox(std::span<const std::uint8_t> bytes, const std::string& name,
                          const VoxOptions& options = {});
Result<VoxImport> readVoxFile(const std::string& path, const VoxOptions& options = {});

// The world alone (materials dropped: every voxel a plain block; warnings dropped).
Result<VoxelWorld> loadVox(const std::string& path, int chunkSize = 32);
Result<VoxelWorld> parseVox(std::span<const std::uint8_t> bytes, const std::string& name,
                            int chunkSize = 32);

// Writing (vox_export.cpp). `materials` (optional) gives the materials of texture slots: voxels
// whose slot has one are written with a MATL for their colour; textured voxels (images) are
// written as their colour, with a warning.
struct VoxExport {
    std::vector<std::uint8_t> bytes;
    std::vector<std::string> warnings;
    int models = 0;  // models written (worlds over 256 per side are split)
};
// Version 200: the palette (RGBA), MATL chunks, and the world as models of at most 256 per side
// placed by a scene graph (nTRN, nGRP, nSHP) so that reading it back gives the same world. Up to
// 255 colours are kept exactly (the most frequent); every other colour is written as the nearest
// kept one (squared RGBA distance), with a warning.
Result<VoxExport> exportVox(const VoxelWorld& world, const MaterialTable* materials = nullptr);
// exportVox's bytes, written through a temporary file and a rename; returns the warnings.
Result<std::vector<std::string>> writeVox(const VoxelWorld& world, const std::string& path,
                                          const MaterialTable* materials = nullptr);
Result<std::vector<std::uint8_t>> encodeVox(const VoxelWorld& world);
Status saveVox(const VoxelWorld& world, const std::string& path);

// The default MagicaVoxel palette, indexed by colour index (entry 0 is unused).
const std::array<Voxel, 256>& defaultVoxPalette();

}  // namespace luxel::voxel
