// The GPU side of the shared voxel traversal (shared/voxel_dda.h; the CPU side is
// src/voxel/voxel_world_access.h): the walk in float (walk_access.glsl) and the accessors over
// the world's storage buffers. Needs `params` (VoxelRenderParams), `voxels[]`, `chunkSolid[]`,
// `brickMasks[]` (uvec2) and `brickReach[]` (uint) declared by the includer (bindings and layout
// in shared/voxel_layout.h).

#include "voxel/walk_access.glsl"

#define LUXEL_VOXEL_WORLD uint
#define LUXEL_BRICK_MASK uvec2

uint chunkIndex(ivec3 cell) {
    const int shift = int(params.chunkShift);
    return (uint(cell.z >> shift) * params.chunksY + uint(cell.y >> shift)) * params.chunksX +
           uint(cell.x >> shift);
}

// The packed voxel at a cell inside the world (VoxelWorld::index).
uint voxelAt(ivec3 cell) {
    const int shift = int(params.chunkShift);
    const int mask = (1 << shift) - 1;
    const uint side = 1u << shift;
    const uint local = (uint(cell.z & mask) * side + uint(cell.y & mask)) * side + uint(cell.x & mask);
    return (chunkIndex(cell) << (3 * shift)) + local;
}

uint voxelValue(ivec3 cell) {
    return voxels[voxelAt(cell)];
}

uint brickIndex(ivec3 brick) {
    return (uint(brick.z) * params.bricksY + uint(brick.y)) * params.bricksX + uint(brick.x);
}

uvec2 voxelBrickMask(uint world, ivec3 brick) {
    return brickMasks[brickIndex(brick)];
}

bool voxelMaskEmpty(uvec2 mask) {
    return (mask.x | mask.y) == 0u;
}

bool voxelMaskBit(uvec2 mask, int bit) {
    const uint word = bit < 32 ? mask.x : mask.y;
    return ((word >> uint(bit & 31)) & 1u) != 0u;
}

// Byte `octant * bricks + brick` of the reach planes, four bytes to a word.
int voxelBrickReach(uint world, ivec3 brick, int octant) {
    const uint bricks = params.bricksX * params.bricksY * params.bricksZ;
    const uint i = uint(octant) * bricks + brickIndex(brick);
    return int((brickReach[i >> 2] >> ((i & 3u) * 8u)) & 0xFFu);
}

bool voxelChunkEmpty(uint world, ivec3 cell) {
    return chunkSolid[chunkIndex(cell)] == 0u;
}

bool voxelSolidAt(uint world, ivec3 cell) {
    return (voxelValue(cell) >> 24) != 0u;
}

#include "shared/voxel_dda.h"

// castRay (dda.h): the first solid voxel along o + t d with entry t in [0, tMax].
Hit castRayLimited(vec3 o, vec3 d, float tMax, int cap, bool jumps) {
    Hit h = missHit();
    if (!finite3(o) || !finite3(d) || (d.x == 0.0 && d.y == 0.0 && d.z == 0.0) || !(tMax >= 0.0)) {
        return h;
    }
    const ivec3 size = ivec3(params.sizeX, params.sizeY, params.sizeZ);
    const bool current = (params.flags & LUXEL_VOXEL_REACH_CURRENT) != 0u;
    const VoxelTrace trace =
        voxelTraverse(0u, size, int(params.chunkShift), o, d, tMax, cap, jumps, current);
    return hitFromTrace(o, d, trace);
}

Hit castRay(vec3 o, vec3 d) {
    return castRayLimited(o, d, LUXEL_INFINITY, int(params.stepCap), true);
}
