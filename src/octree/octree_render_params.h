// OctreeRenderParams (shared/octree_layout.h) from a tree, a camera and render options, filled in
// one place for the CPU twin and the GPU passes.
#pragma once

#include "gpu/shaders/shared/octree_layout.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/voxel/camera.h"

namespace luxel::octree {

// Everything but the camera: the tree, the light (the stride resolved, 0 unless the volume mode
// scatters), the medium and the mode; what the light cache depends on.
gpu::shared::OctreeRenderParams mediumParams(const Octree& tree,
                                             const OctreeRenderOptions& options);

// Refuses, with the numbers, a light cache grid too large for the memory or for uint indices.
Status checkLightCacheSize(const gpu::shared::OctreeRenderParams& params);

gpu::shared::OctreeRenderParams renderParams(const Octree& tree, const voxel::Camera& camera,
                                             const OctreeRenderOptions& options);

}  // namespace luxel::octree
