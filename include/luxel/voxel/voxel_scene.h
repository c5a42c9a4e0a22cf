// Voxel scene files: JSON with the world source (a generator and its parameters, or a MagicaVoxel
// file), the camera, the sun, the sky and render options. Format: docs/scene-format-voxel.md.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/post/post_options.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

struct VoxelScene {
    VoxelWorld world;
    Camera camera;
    ShadeOptions shading;
    std::string sourcePath;
    TextureSet textures;     // the scene's "textures", in slot order
    post::PostOptions post;  // the scene's "post": bloom, tone, internal resolution
    // What a .vox world could not apply ("m.vox: MATL 37: ..."), for the caller to print.
    std::vector<std::string> warnings = {};
};

// Reads a scene, builds its world (generators run here) and validates everything. Errors name the
// file, line:column and field. `width`/`height` > 0 override the camera's image size.
Result<VoxelScene> loadVoxelScene(const std::string& path, int width = 0, int height = 0);
// The same from the scene's text; `path` is used in messages and resolves the files the scene
// names (textures, .vox worlds) relative to its folder.
Result<VoxelScene> parseVoxelScene(std::string_view text, const std::string& path, int width = 0,
                                   int height = 0);
// (A file of either kind: luxel/scene/scene_file.h reads it once and picks the reader.)

}  // namespace luxel::voxel
