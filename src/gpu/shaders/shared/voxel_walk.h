// The Amanatides & Woo (1987) walk both voxel structures traverse: the per-cell state, one step,
// an exact jump out of an empty box of cells, the start (slab clip, first cell, entry face), and
// where a hit lies on its face. The dense world (voxel_dda.h) and the sparse voxel octree
// (octree_walk.h) drive it with their own emptiness tests, so both visit exactly the cells of the
// per-voxel loop and agree hit for hit (docs/algorithms/voxel-traversal.md; conventions and edge
// cases in include/luxel/voxel/dda.h). Compiled as C++ (double) and as GLSL (float).
//
// The includer defines, before including this file:
// - LUXEL_REAL / LUXEL_REAL3: the scalar and 3-vector type (double/dvec3 on the CPU, float/vec3 on
//   the GPU);
// - LUXEL_REAL voxelNextToward(LUXEL_REAL x, LUXEL_REAL toward): the next representable value
//   (std::nextafter in C++).
#ifndef LUXEL_GPU_SHARED_VOXEL_WALK_H
#define LUXEL_GPU_SHARED_VOXEL_WALK_H

#include "glsl_compat.h"

// Box jumps find the cell on the other axes by stepping from the current one when the box is at
// most this many cells across (few crossings: cheaper than a floor and checks), else by floor.
#define LUXEL_VOXEL_SHORT_WALK 8

LUXEL_SHARED_BEGIN

// Traversal state of the per-voxel loop: the current cell, the t it was entered at and through
// which axis (-1: none), and the t of the next boundary on each axis. `stp` and `next`, written at
// a run-time axis every step, are arrays; the rest are vectors, which the C++ compiler keeps in
// registers (measured: all-array state is 25% slower on the CPU).
struct VoxelWalk {
    LUXEL_REAL3 o;
    LUXEL_REAL3 d;
    LUXEL_REAL3 inv;  // 1 / d (inf on zero components, which never step)
    ivec3 size;
    int stp[3];
    ivec3 cell;
    LUXEL_REAL next[3];
    LUXEL_REAL t;
    int axis;
};

// What a traversal found: the first solid cell, its entry t and axis, or a miss; `capped` when the
// step cap ended it; `steps` = voxel visits plus block jumps.
struct VoxelTrace {
    bool hit;
    bool capped;
    ivec3 cell;
    LUXEL_REAL t;
    int axis;
    ivec3 stp;
    int steps;
};

// t at which the ray leaves `cell` on one axis. The single formula used for every boundary, so a
// boundary's t is bit-identical however the traversal reached it (plain steps or a block jump).
// A multiplication by the precomputed 1 / direction keeps a division off the loop's critical path.
LUXEL_FUNC_HOT LUXEL_REAL voxelExitT(int cell, int stp, LUXEL_REAL o, LUXEL_REAL inverseDirection) {
    return (LUXEL_REAL(cell + (stp > 0 ? 1 : 0)) - o) * inverseDirection;
}

// floor for |x| well inside int range, without a library call on baseline x86-64.
LUXEL_FUNC_HOT int voxelFloorToInt(LUXEL_REAL x) {
    const int i = int(x);  // truncates towards zero
    return i - (LUXEL_REAL(i) > x ? 1 : 0);
}

LUXEL_FUNC_HOT LUXEL_REAL voxelExitAt(LUXEL_IN(VoxelWalk) w, int c, int a) {
    return voxelExitT(c, w.stp[a], w.o[a], w.inv[a]);
}

// One A&W step; strict order x, y, z on ties (Amanatides & Woo's comparison chain). False when
// the ray leaves the world or passes tMax.
LUXEL_FUNC_HOT bool voxelStepOne(LUXEL_INOUT(VoxelWalk) w, LUXEL_REAL tMax) {
    const int a = w.next[0] <= w.next[1] ? (w.next[0] <= w.next[2] ? 0 : 2)
                                         : (w.next[1] <= w.next[2] ? 1 : 2);
    if (w.next[a] == LUXEL_REAL(LUXEL_INFINITY)) return false;
    w.t = w.next[a];
    w.cell[a] += w.stp[a];
    w.axis = a;
    if (w.cell[a] < 0 || w.cell[a] >= w.size[a] || w.t > tMax) return false;
    w.next[a] = voxelExitAt(w, w.cell[a], a);
    return true;
}

// Jumps to the state the per-voxel loop reaches when it leaves the box of cells [lo, hi] (which
// holds the current cell and no solid voxel): the first box plane crossed, lowest axis on ties,
// exactly as voxelStepOne orders its steps. False when that leaves the world or passes tMax.
LUXEL_FUNC_HOT bool voxelLeaveBox(LUXEL_INOUT(VoxelWalk) w, ivec3 lo, ivec3 hi, LUXEL_REAL tMax) {
    int a = -1;
    LUXEL_REAL tJump = LUXEL_REAL(LUXEL_INFINITY);
    LUXEL_UNROLL_AXES
    for (int b = 0; b < 3; ++b) {
        if (w.stp[b] == 0) continue;
        const LUXEL_REAL tb = voxelExitAt(w, w.stp[b] > 0 ? hi[b] : lo[b], b);
        if (tb < tJump) {
            tJump = tb;
            a = b;
        }
    }
    if (a < 0 || tJump == LUXEL_REAL(LUXEL_INFINITY)) return false;
    // The other axes: the first cell whose exit the plain loop has not yet taken when it steps
    // axis a at tJump ("crossed": earlier, or tied and a lower axis).
    LUXEL_UNROLL_AXES
    for (int b = 0; b < 3; ++b) {
        if (b == a || w.stp[b] == 0) continue;
        const int first = w.cell[b];
        const int last = w.stp[b] > 0 ? hi[b] : lo[b];
        int c = first;
        LUXEL_REAL tb = w.next[b];
        if (abs(last - first) > LUXEL_VOXEL_SHORT_WALK && (tb < tJump || (tb == tJump && b < a))) {
            // A long way to go: start next to where the ray is at tJump, then correct.
            c = voxelFloorToInt(
                clamp(w.o[b] + tJump * w.d[b], LUXEL_REAL(-1), LUXEL_REAL(w.size[b] + 1)));
            c = w.stp[b] > 0 ? clamp(c, first, last) : clamp(c, last, first);
            for (;;) {
                if (c == first) break;
                const LUXEL_REAL tc = voxelExitAt(w, c - w.stp[b], b);
                if (tc < tJump || (tc == tJump && b < a)) break;
                c -= w.stp[b];
            }
            tb = voxelExitAt(w, c, b);
        }
        // Step on while the plain loop would already have left the cell.
        while (c != last && (tb < tJump || (tb == tJump && b < a))) {
            c += w.stp[b];
            tb = voxelExitAt(w, c, b);
        }
        w.cell[b] = c;
        w.next[b] = tb;
    }
    w.t = tJump;
    w.cell[a] = w.stp[a] > 0 ? hi[a] + 1 : lo[a] - 1;
    w.axis = a;
    if (w.cell[a] < 0 || w.cell[a] >= w.size[a] || w.t > tMax) return false;
    w.next[a] = voxelExitAt(w, w.cell[a], a);
    return true;
}

LUXEL_FUNC_HOT ivec3 voxelStep(LUXEL_IN(VoxelWalk) w) {
    return ivec3(w.stp[0], w.stp[1], w.stp[2]);
}

LUXEL_FUNC VoxelTrace voxelMiss(int steps, bool capped) {
    return VoxelTrace(false, capped, ivec3(0), LUXEL_REAL(LUXEL_INFINITY), -1, ivec3(0), steps);
}

// Sets up the walk: slab clip against [0, size], start cell, entry face. False on a miss. A zero
// component (either sign) constrains nothing but the origin: the ray belongs to the cells
// floor(o), which must exist. Ties on entry keep the highest axis (the plane crossed last under
// the x-then-y-then-z step order). The world planes use the formula of every cell boundary (the
// reciprocal), so t values are consistent.
LUXEL_FUNC_HOT bool voxelStart(LUXEL_INOUT(VoxelWalk) w, LUXEL_REAL tMax) {
    LUXEL_REAL tEnter = -LUXEL_REAL(LUXEL_INFINITY);
    LUXEL_REAL tExit = LUXEL_REAL(LUXEL_INFINITY);
    int enterAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (w.d[a] == LUXEL_REAL(0)) {
            if (!(w.o[a] >= LUXEL_REAL(0) && w.o[a] < LUXEL_REAL(w.size[a]))) return false;
            continue;
        }
        LUXEL_REAL t0 = (LUXEL_REAL(0) - w.o[a]) * w.inv[a];
        LUXEL_REAL t1 = (LUXEL_REAL(w.size[a]) - w.o[a]) * w.inv[a];
        if (t0 > t1) {
            const LUXEL_REAL swap = t0;
            t0 = t1;
            t1 = swap;
        }
        if (t0 >= tEnter) {
            tEnter = t0;
            enterAxis = a;
        }
        tExit = min(tExit, t1);
    }
    const LUXEL_REAL t0 = max(tEnter, LUXEL_REAL(0));
    // Miss: the box is behind or beside the ray, or the origin is on its boundary moving out.
    // A ray grazing an edge from outside (tEnter == tExit > 0) touches it and counts.
    if (tEnter > tExit || tExit < t0 || (tExit == t0 && tEnter < t0) || t0 > tMax) return false;

    const bool fromOutside = tEnter >= LUXEL_REAL(0);
    for (int a = 0; a < 3; ++a) {
        w.stp[a] = w.d[a] > LUXEL_REAL(0) ? 1 : (w.d[a] < LUXEL_REAL(0) ? -1 : 0);
        if (fromOutside && a == enterAxis) {
            w.cell[a] = w.stp[a] > 0 ? 0 : w.size[a] - 1;
            continue;
        }
        const LUXEL_REAL p = t0 == LUXEL_REAL(0) ? w.o[a] : w.o[a] + t0 * w.d[a];
        int f = voxelFloorToInt(clamp(p, LUXEL_REAL(-1), LUXEL_REAL(w.size[a])));
        // On a boundary and moving down: the ray is in the lower cell straight away.
        if (p == LUXEL_REAL(f) && w.stp[a] < 0) f -= 1;
        w.cell[a] = clamp(f, 0, w.size[a] - 1);
    }

    // The face the first cell is entered through: the world face, or for an origin inside the
    // world the cell face the origin lies on (t == 0); none when strictly inside.
    w.axis = -1;
    if (fromOutside) {
        w.axis = enterAxis;
    } else {
        LUXEL_REAL best = -LUXEL_REAL(LUXEL_INFINITY);
        for (int a = 0; a < 3; ++a) {
            if (w.stp[a] == 0) continue;
            const LUXEL_REAL te = voxelExitT(w.cell[a], -w.stp[a], w.o[a], w.inv[a]);
            if (te >= best) {
                best = te;
                w.axis = a;
            }
        }
        if (!(best >= LUXEL_REAL(0))) w.axis = -1;  // -0.0 >= 0: an origin on the face counts
    }
    w.t = t0;
    for (int a = 0; a < 3; ++a) {
        w.next[a] = w.stp[a] != 0 ? voxelExitAt(w, w.cell[a], a) : LUXEL_REAL(LUXEL_INFINITY);
    }
    return true;
}

// Where a hit lies: the point on the ray, clamped into the hit cell and snapped onto the entry
// face's plane (so secondary rays start exactly on the face), and the face coordinates in [0, 1)
// as in the Unity voxel ray tracer: x faces (z, y), z faces (x, y), y faces and origins inside a
// voxel (x, z).
struct VoxelSurface {
    LUXEL_REAL3 point;
    float u;
    float v;
};

LUXEL_FUNC float voxelFaceFraction(LUXEL_REAL p, int cell) {
    return clamp(float(p - LUXEL_REAL(cell)), 0.0f, 0.99999994f);  // [0, nextafter(1, 0)]
}

LUXEL_FUNC VoxelSurface voxelSurface(LUXEL_REAL3 o, LUXEL_REAL3 d, VoxelTrace trace) {
    VoxelSurface s;
    for (int a = 0; a < 3; ++a) {
        const LUXEL_REAL p = trace.t == LUXEL_REAL(0) ? o[a] : o[a] + trace.t * d[a];
        s.point[a] = clamp(p, LUXEL_REAL(trace.cell[a]), LUXEL_REAL(trace.cell[a]) + LUXEL_REAL(1));
    }
    const int axis = trace.axis;
    if (axis >= 0) s.point[axis] = LUXEL_REAL(trace.cell[axis] + (trace.stp[axis] > 0 ? 0 : 1));
    int uAxis = 0;
    int vAxis = 2;
    if (axis == 0) {
        uAxis = 2;
        vAxis = 1;
    }
    if (axis == 2) {
        uAxis = 0;
        vAxis = 1;
    }
    s.u = voxelFaceFraction(s.point[uAxis], trace.cell[uAxis]);
    s.v = voxelFaceFraction(s.point[vAxis], trace.cell[vAxis]);
    return s;
}

// Where a ray o + t d restarts after passing through `cell` (a cutout texel lets it through):
// the point where it leaves the cell, placed so the traversal started there enters the neighbour
// the per-voxel loop would, with edge and corner ties kept in its axis order (x, then y, then z).
LUXEL_FUNC LUXEL_REAL3 voxelContinueThrough(LUXEL_REAL3 o, LUXEL_REAL3 d, ivec3 cell) {
    LUXEL_REAL exitOf[3];
    int exitAxis = -1;
    for (int a = 0; a < 3; ++a) {
        exitOf[a] = LUXEL_REAL(LUXEL_INFINITY);
        if (d[a] == LUXEL_REAL(0)) continue;
        exitOf[a] = (LUXEL_REAL(cell[a] + (d[a] > LUXEL_REAL(0) ? 1 : 0)) - o[a]) / d[a];
        if (exitAxis < 0 || exitOf[a] < exitOf[exitAxis]) exitAxis = a;
    }
    if (exitAxis < 0) return o;  // zero direction: the traversal misses it anyway
    const LUXEL_REAL tExit = exitOf[exitAxis];
    LUXEL_REAL previous = LUXEL_REAL(0);
    LUXEL_REAL3 next = o;
    for (int a = 0; a < 3; ++a) {
        const LUXEL_REAL lo = LUXEL_REAL(cell[a]);
        const LUXEL_REAL hi = LUXEL_REAL(cell[a] + 1);
        const LUXEL_REAL boundary = LUXEL_REAL(cell[a] + (d[a] > LUXEL_REAL(0) ? 1 : 0));
        LUXEL_REAL p = d[a] == LUXEL_REAL(0) ? o[a] : o[a] + tExit * d[a];
        if (a == exitAxis) {
            p = boundary;  // on the boundary: the traversal starts in the neighbour
        } else if (d[a] != LUXEL_REAL(0) && exitOf[a] == tExit) {
            // A tie (the ray leaves through an edge or a corner): the traversal steps this axis
            // right after the exit axis, higher axes later. Start just inside the boundary, far
            // enough that the restarted traversal crosses it after the previous tied axis,
            // beginning where the ray is at t = previous. Bounded: a flushed denormal on the GPU
            // could otherwise stall the walk.
            const LUXEL_REAL inside = d[a] > LUXEL_REAL(0) ? lo : hi;
            p = boundary - previous * d[a];
            LUXEL_REAL t = LUXEL_REAL(0);
            for (int i = 0; i < 64; ++i) {
                p = voxelNextToward(p, inside);
                t = (boundary - p) / d[a];
                if (t > previous) break;
            }
            previous = t;
        } else if (d[a] > LUXEL_REAL(0)) {
            p = clamp(p, lo, voxelNextToward(hi, lo));  // hi would start one cell on
        } else if (d[a] < LUXEL_REAL(0)) {
            p = clamp(p, voxelNextToward(lo, hi), hi);  // lo would start one cell lower
        }
        next[a] = p;
    }
    return next;
}

LUXEL_SHARED_END

#endif
