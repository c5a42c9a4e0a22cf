// The CPU side of the shared voxel traversal (src/gpu/shaders/shared/voxel_dda.h): the walk in
// double (walk_access.h), and the accessors over a VoxelWorld's brick masks, brick reach and
// chunk counts. The GPU side is src/gpu/shaders/voxel/voxel_world_access.glsl.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "gpu/shaders/shared/glsl_compat.h"
#include "luxel/voxel/voxel_world.h"
#include "voxel/walk_access.h"

#define LUXEL_VOXEL_WORLD const ::luxel::voxel::VoxelWorld&
#define LUXEL_BRICK_MASK std::uint64_t

namespace luxel::gpu::shared {

inline std::uint64_t voxelBrickMask(const voxel::VoxelWorld& w, ivec3 b) {
    return w.brickMask(b.x, b.y, b.z);
}

inline bool voxelMaskEmpty(std::uint64_t mask) {
    return mask == 0;
}

inline bool voxelMaskBit(std::uint64_t mask, int bit) {
    return ((mask >> bit) & 1u) != 0;
}

inline int voxelBrickReach(const voxel::VoxelWorld& w, ivec3 b, int octant) {
    return w.brickReach(octant, b.x, b.y, b.z);
}

inline bool voxelChunkEmpty(const voxel::VoxelWorld& w, ivec3 cell) {
    const int shift = std::countr_zero(static_cast<unsigned>(w.chunkSize()));
    return w.chunkSolidCount(cell.x >> shift, cell.y >> shift, cell.z >> shift) == 0;
}

inline bool voxelSolidAt(const voxel::VoxelWorld& w, ivec3 cell) {
    return w.solid(cell.x, cell.y, cell.z);
}

}  // namespace luxel::gpu::shared

#include "gpu/shaders/shared/voxel_dda.h"
