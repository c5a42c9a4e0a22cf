// The voxel scene reader on an already parsed document, for the one scene-file loader
// (luxel/scene/scene_file.h), which reads and parses a file once whatever its type.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/json_fields.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::voxel {

// The parts other scene types share (octree scenes, luxel/scene/scene_file.h); both throw
// json::Invalid naming the field. A world's "textures" come from its scene.
VoxelWorld worldFromJson(const json::Json& world, const std::filesystem::path& baseDir,
                         const TextureSet& textures);
Camera cameraFromJson(const json::Json& camera, int width, int height);

// Whether a parsed scene document declares "type": "voxel".
bool isVoxelScene(const json::Json& root);

// `text` is the document's source (errors are located in it); `path` resolves relative files.
Result<VoxelScene> voxelSceneFromJson(const json::Json& root, std::string_view text,
                                      const std::string& path, int width = 0, int height = 0);

}  // namespace luxel::voxel
