// The voxel ray traversal both backends run: Amanatides & Woo (1987) with exact jumps over empty
// space (docs/algorithms/voxel-traversal.md; conventions and edge cases in
// include/luxel/voxel/dda.h). One definition, compiled as C++ (in double, by castRay in
// src/voxel/dda.cpp) and as GLSL (in float, by the voxel shaders).
//
// The includer defines, before including this file:
// - LUXEL_REAL / LUXEL_REAL3: the scalar and 3-vector type (double/dvec3 on the CPU, float/vec3 on
//   the GPU);
// - LUXEL_VOXEL_WORLD: the type of the world handle passed through to the accessors (a reference
//   to the VoxelWorld in C++, an unused uint in GLSL, whose world lives in storage buffers);
// - the accessors, for cells and bricks inside the world:
//     LUXEL_BRICK_MASK voxelBrickMask(LUXEL_VOXEL_WORLD w, ivec3 brick)  64-bit occupancy
//     bool voxelMaskEmpty(LUXEL_BRICK_MASK m), bool voxelMaskBit(LUXEL_BRICK_MASK m, int bit)
//   with LUXEL_BRICK_MASK the mask's type (uint64 in C++, uvec2 in GLSL) and bits in
//   VoxelWorld::brickBit order;
//     int  voxelBrickReach(LUXEL_VOXEL_WORLD w, ivec3 brick, int octant)  directional reach
//       (VoxelWorld::brickReach: octant bit a set when the ray moves towards -inf on axis a)
//     bool voxelChunkEmpty(LUXEL_VOXEL_WORLD w, ivec3 cell)            chunk holding `cell`
//     bool voxelSolidAt(LUXEL_VOXEL_WORLD w, ivec3 cell)               alpha != 0
// - what voxel_walk.h needs (voxelNextToward).
#ifndef LUXEL_GPU_SHARED_VOXEL_DDA_H
#define LUXEL_GPU_SHARED_VOXEL_DDA_H

#include "glsl_compat.h"
#include "voxel_walk.h"

// Side of a brick, as a shift (VoxelWorld::kBrickShift).
#define LUXEL_VOXEL_BRICK_SHIFT 2

LUXEL_SHARED_BEGIN

// The first solid voxel along o + t d with entry t in [0, tMax], within `cap` loop iterations.
// `jumps`: skip empty space (brick masks, then the empty cube of bricks the brick's reach gives
// towards the ray's octant when `reachCurrent`, else the empty chunk or brick); otherwise visit
// every voxel. Both give the same hit; only `steps` differs. o and d must be finite and d non-zero.
LUXEL_FUNC_HOT VoxelTrace voxelTraverse(LUXEL_VOXEL_WORLD world, ivec3 size, int chunkShift,
                                        LUXEL_REAL3 o, LUXEL_REAL3 d, LUXEL_REAL tMax, int cap,
                                        bool jumps, bool reachCurrent) {
    VoxelWalk w;
    w.o = o;
    w.d = d;
    w.inv = LUXEL_REAL3(LUXEL_REAL(1) / d.x, LUXEL_REAL(1) / d.y, LUXEL_REAL(1) / d.z);
    w.size = size;
    if (!voxelStart(w, tMax)) return voxelMiss(0, false);
    int steps = 0;
    if (!jumps) {
        for (;;) {
            if (steps >= cap) return voxelMiss(steps, true);
            ++steps;
            if (voxelSolidAt(world, w.cell)) {
                return VoxelTrace(true, false, w.cell, w.t, w.axis, voxelStep(w), steps);
            }
            if (!voxelStepOne(w, tMax)) return voxelMiss(steps, false);
        }
    }
    const int brickShift = LUXEL_VOXEL_BRICK_SHIFT;
    for (;;) {
        if (steps >= cap) return voxelMiss(steps, true);
        ++steps;
        const ivec3 c = w.cell;
        const ivec3 b = ivec3(c.x >> brickShift, c.y >> brickShift, c.z >> brickShift);
        const LUXEL_BRICK_MASK mask = voxelBrickMask(world, b);
        if (!voxelMaskEmpty(mask)) {
            const int m = (1 << brickShift) - 1;
            const int bit = ((c.z & m) << (2 * brickShift)) | ((c.y & m) << brickShift) | (c.x & m);
            if (voxelMaskBit(mask, bit)) {
                return VoxelTrace(true, false, c, w.t, w.axis, voxelStep(w), steps);
            }
            if (!voxelStepOne(w, tMax)) return voxelMiss(steps, false);
            continue;
        }
        // An empty brick: leave the empty cube of bricks from it towards the ray's octant when
        // the reach is current (it holds the current cell, so the jump is exact), else the whole
        // chunk when it is empty, else just the brick.
        ivec3 lo, hi;
        if (reachCurrent) {
            const int octant =
                (w.stp[0] < 0 ? 1 : 0) | (w.stp[1] < 0 ? 2 : 0) | (w.stp[2] < 0 ? 4 : 0);
            const int r = voxelBrickReach(world, b, octant) - 1;
            for (int a = 0; a < 3; ++a) {
                const bool down = w.stp[a] < 0;
                lo[a] = max((b[a] - (down ? r : 0)) << brickShift, 0);
                hi[a] = min((b[a] + (down ? 0 : r) + 1) << brickShift, size[a]) - 1;
            }
        } else {
            const int shift = voxelChunkEmpty(world, c) ? chunkShift : brickShift;
            for (int a = 0; a < 3; ++a) {
                lo[a] = (c[a] >> shift) << shift;
                hi[a] = min(lo[a] + (1 << shift), size[a]) - 1;
            }
        }
        if (!voxelLeaveBox(w, lo, hi, tMax)) return voxelMiss(steps, false);
    }
}

LUXEL_SHARED_END

#endif
