// Octree scene files ("type": "octree"): where the octree comes from (a procedural phantom or
// terrain, a voxel world, an .lxo container or an OpenVDB grid), the camera and the render
// options. Format: docs/scene-format-octree.md. Loaded through luxel/scene/scene_file.h.
#pragma once

#include <string>

#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/voxel/camera.h"

namespace luxel::scene {

struct OctreeScene {
    octree::Octree tree;
    voxel::Camera camera;
    octree::OctreeRenderOptions render;
    std::string sourcePath;
    std::string source;  // what the tree was made from ("phantom 256", "file x.lxo", ...)
    double buildSeconds = 0;
};

}  // namespace luxel::scene
