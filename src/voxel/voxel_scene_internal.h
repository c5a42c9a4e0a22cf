// The voxel scene reader on an already parsed document, for the one scene-file loader
// (luxel/scene/scene_file.h), which reads and parses a file once whatever its type.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/json_fields.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::voxel {

// The parts other scene types share (octree scenes, luxel/scene/scene_file.h); both throw
// json::Invalid naming the field. A world's "textures" come from its scene.
// A "vox" source's materials take texture slots after the scene's own and its warnings are
// collected, when `voxExtras` is given (else its voxels are plain blocks); `voxFrame` >= 0
// overrides the world's "frame".
struct VoxWorldExtras {
    TextureSet* textures = nullptr;
    MaterialTable* table = nullptr;
    std::vector<std::string>* warnings = nullptr;
    int voxFrame = -1;
};
VoxelWorld worldFromJson(const json::Json& world, const std::filesystem::path& baseDir,
                         const TextureSet& textures, const VoxWorldExtras& voxExtras = {});
Camera cameraFromJson(const json::Json& camera, int width, int height);

// Whether a parsed scene document declares "type": "voxel".
bool isVoxelScene(const json::Json& root);

// `text` is the document's source (errors are located in it); `path` resolves relative files.
// `voxFrame` >= 0 overrides a "vox" world's "frame".
Result<VoxelScene> voxelSceneFromJson(const json::Json& root, std::string_view text,
                                      const std::string& path, int width = 0, int height = 0,
                                      int voxFrame = -1);

}  // namespace luxel::voxel
