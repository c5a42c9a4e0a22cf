// OctreeRenderParams (shared/octree_layout.h) from a tree, a camera and render options, filled in
// one place for the CPU twin and the GPU pass.
#pragma once

#include "gpu/shaders/shared/octree_layout.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/voxel/camera.h"

namespace luxel::octree {

gpu::shared::OctreeRenderParams renderParams(const Octree& tree, const voxel::Camera& camera,
                                             const OctreeRenderOptions& options);

}  // namespace luxel::octree
