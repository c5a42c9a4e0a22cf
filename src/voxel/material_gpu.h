// Materials as the GPU reads them (binding 9 of voxel_render, src/gpu/shaders/shared/
// voxel_layout.h): the CPU's MaterialTable packed into VoxelMaterial records.
#pragma once

#include <vector>

#include "gpu/shaders/shared/voxel_layout.h"
#include "luxel/voxel/material.h"

namespace luxel::voxel {

// One record per texture slot (the slot's own material, else the plain one), then the plain
// blocks' material at LUXEL_VOXEL_PLAIN_MATERIAL.
std::vector<gpu::shared::VoxelMaterial> gpuMaterials(const MaterialTable& table);

}  // namespace luxel::voxel
