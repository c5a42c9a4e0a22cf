// A voxel scene straight from a MagicaVoxel .vox file (`luxel render m.vox`, `luxel-view m.vox`):
// the file's world and materials, physical lighting, and a camera that frames the whole world
// from above at three quarters. Format notes: docs/scene-format-voxel.md.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/voxel/vox_import.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::voxel {

struct VoxSceneOptions {
    int width = 0, height = 0;  // camera image size (0: 960 x 540)
    int frame = 0;              // animation frame (vox_import.h)
    int chunkSize = 32;
};

Result<VoxelScene> loadVoxScene(const std::string& path, const VoxSceneOptions& options = {});
// The same from the file's bytes; `path` names it in messages.
Result<VoxelScene> voxSceneFromBytes(std::span<const std::uint8_t> bytes, const std::string& path,
                                     const VoxSceneOptions& options = {});

// A camera looking at the centre of a world of `worldSize` voxels from above (30 degrees) and the
// front right (45 degrees: MagicaVoxel's front, vox -y, is luxel -z), as near as it can be with
// every corner of the world inside the image (and a margin).
Result<Camera> framingCamera(Int3 worldSize, int width, int height);
// The same for a set of points that must all be seen, looking at the centre of their box (a
// .vox scene frames the outline of the bricks that hold solid voxels).
Result<Camera> framingCamera(const std::vector<Vec3d>& points, int width, int height);

// Adds an import's materials to a scene's texture slots (after those it has: "material:vox N",
// one white texel) and their materials to `table`, renumbering the world's material bytes to
// match. Fails when the slots would exceed kMaxTextures.
Status addVoxMaterials(VoxImport& import, TextureSet& textures, MaterialTable& table);

// Whether `path` ends in ".vox" (any case).
bool hasVoxExtension(const std::string& path);
// Whether the bytes start with the "VOX " magic.
bool hasVoxMagic(std::span<const std::uint8_t> bytes);

}  // namespace luxel::voxel
