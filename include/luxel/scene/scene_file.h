// One reader for every scene file luxel takes: the file is read and parsed once, its "type" picks
// the reader ("voxel" for voxel scenes, "octree" for sparse voxel octrees; no type, or "2d", for
// the 2D solvers; a MagicaVoxel file, by its .vox extension or "VOX " magic, is a voxel scene
// with a camera that frames it: luxel/voxel/vox_scene.h), and errors are
// located at file:line:column with one wording for both. Used by the CLI, the viewer and the
// benches, so nothing reads a scene twice to learn its type.
#pragma once

#include <string>
#include <variant>

#include "luxel/core/error.h"
#include "luxel/core/image_size.h"
#include "luxel/gi2d/scene2d.h"
#include "luxel/scene/octree_scene.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::scene {

enum class SceneKind { TwoD, Voxel, Octree };

struct SceneFile {
    std::string path;
    std::variant<gi2d::Scene2D, voxel::VoxelScene, OctreeScene> content;

    SceneKind kind() const { return static_cast<SceneKind>(content.index()); }
    gi2d::Scene2D& twoD() { return std::get<gi2d::Scene2D>(content); }
    voxel::VoxelScene& voxel() { return std::get<voxel::VoxelScene>(content); }
    OctreeScene& octree() { return std::get<OctreeScene>(content); }
};

struct SceneFileOptions {
    // Voxel and octree scenes: the camera's image size instead of the file's (0 x 0: the file's).
    ImageSize voxelImageSize;
    // MagicaVoxel worlds (.vox files and "vox" sources): the animation frame (-1: the scene's
    // "frame", else 0).
    int voxFrame = -1;
};

Result<SceneFile> loadSceneFile(const std::string& path, const SceneFileOptions& options = {});

}  // namespace luxel::scene
