// The CPU side of the shared octree traversal (src/gpu/shaders/shared/octree_walk.h): the walk in
// double (voxel/walk_access.h) and the entry accessor over the array. The GPU side is
// src/gpu/shaders/octree/octree_access.glsl.
#pragma once

#include <cstdint>

#include "voxel/walk_access.h"

#define LUXEL_OCTREE const std::uint32_t*

namespace luxel::gpu::shared {

inline uint octreeEntry(const std::uint32_t* nodes, uint index) {
    return nodes[index];
}

}  // namespace luxel::gpu::shared

#include "gpu/shaders/shared/octree_walk.h"
