// One reader for every scene file luxel takes: the file is read and parsed once, its "type" picks
// the reader ("voxel" for voxel scenes; no type, or "2d", for the 2D solvers), and errors are
// located at file:line:column with one wording for both. Used by the CLI, the viewer and the
// benches, so nothing reads a scene twice to learn its type.
#pragma once

#include <string>
#include <variant>

#include "luxel/core/error.h"
#include "luxel/core/image_size.h"
#include "luxel/gi2d/scene2d.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::scene {

enum class SceneKind { TwoD, Voxel };

struct SceneFile {
    std::string path;
    std::variant<gi2d::Scene2D, voxel::VoxelScene> content;

    SceneKind kind() const {
        return std::holds_alternative<voxel::VoxelScene>(content) ? SceneKind::Voxel
                                                                  : SceneKind::TwoD;
    }
    gi2d::Scene2D& twoD() { return std::get<gi2d::Scene2D>(content); }
    voxel::VoxelScene& voxel() { return std::get<voxel::VoxelScene>(content); }
};

struct SceneFileOptions {
    // Voxel scenes: the camera's image size instead of the file's (0 x 0: the file's).
    ImageSize voxelImageSize;
};

Result<SceneFile> loadSceneFile(const std::string& path, const SceneFileOptions& options = {});

}  // namespace luxel::scene
