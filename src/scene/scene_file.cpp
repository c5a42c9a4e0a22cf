#include "luxel/scene/scene_file.h"

#include <algorithm>
#include <filesystem>
#include <span>

#include "core/json_fields.h"
#include "gi2d/scene2d_json_internal.h"
#include "luxel/core/file_io.h"
#include "luxel/voxel/vox_scene.h"
#include "scene/octree_scene_internal.h"
#include "voxel/voxel_scene_internal.h"

namespace luxel::scene {

Result<SceneFile> loadSceneFile(const std::string& path, const SceneFileOptions& options) {
    const voxel::VoxSceneOptions vox{options.voxelImageSize.width, options.voxelImageSize.height,
                                     std::max(options.voxFrame, 0)};
    if (voxel::hasVoxExtension(path)) {
        auto scene = voxel::loadVoxScene(path, vox);
        if (!scene) return scene.error();
        return SceneFile{path, std::move(*scene)};
    }
    auto text = readFileBytes(path, "scene");
    if (!text) return text.error();
    const std::span bytes(reinterpret_cast<const std::uint8_t*>(text->data()), text->size());
    if (voxel::hasVoxMagic(bytes)) {
        auto scene = voxel::voxSceneFromBytes(bytes, path, vox);
        if (!scene) return scene.error();
        return SceneFile{path, std::move(*scene)};
    }
    auto root = json::parse(*text, path);
    if (!root) return root.error();
    if (voxel::isVoxelScene(*root)) {
        auto scene = voxel::voxelSceneFromJson(*root, *text, path, options.voxelImageSize.width,
                                               options.voxelImageSize.height, options.voxFrame);
        if (!scene) return scene.error();
        return SceneFile{path, std::move(*scene)};
    }
    if (isOctreeScene(*root)) {
        auto scene = octreeSceneFromJson(*root, *text, path, options.voxelImageSize.width,
                                         options.voxelImageSize.height);
        if (!scene) return scene.error();
        return SceneFile{path, std::move(*scene)};
    }
    auto scene = gi2d::scene2DFromJson(*root, *text, path,
                                       std::filesystem::path(path).parent_path().string());
    if (!scene) return scene.error();
    return SceneFile{path, std::move(*scene)};
}

}  // namespace luxel::scene
