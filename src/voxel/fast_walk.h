// The CPU's own loop for the shared voxel traversal (src/gpu/shaders/shared/voxel_dda.h with the
// brick reach current): the same visits and jumps, in the same order, with the same double
// arithmetic, hence the same hit, t and loop count bit for bit, but written for a CPU
// (docs/algorithms/voxel-traversal.md §4):
// - the per-axis state lives in named scalars (three Axis values the compiler keeps in
//   registers) instead of arrays indexed by a run-time axis;
// - a voxel step branches on its axis (no indexed store), tests one comparison for an infinite
//   boundary or tMax, and moves the cell's bit in the brick mask by a constant per axis;
// - a ray whose origin lies at least a voxel inside every face starts in its origin's cell
//   without the slab clip (startDeepInside);
// - a jump finds the cell on the other axes from floor(o + t d) and corrects it by the exit-t
//   test (at most a step or two), whatever the size of the box.
// The result equals the shared kernel's because every cell boundary uses the one formula
// (voxelExitT), which is monotone in the cell index, so "the first cell whose exit the loop has not
// yet taken" is one cell however it is searched for.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <utility>

#include "voxel/skip_jump.h"
#include "voxel/voxel_world_access.h"

namespace luxel::voxel::fast {

namespace shared = gpu::shared;

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// One axis of the walk: ray, cell and the t of the cell's exit boundary.
struct Axis {
    double o, d, inv;
    int stp, size, cell;
    double next;
    int up = stp > 0 ? 1 : 0;  // the exit boundary's offset from the cell

    // voxelExitT for this axis (the formula of every boundary).
    double exitAt(int c) const { return (double(c + up) - o) * inv; }
};

// Whether the fast loop takes this ray: the brick reach is current and every non-zero
// direction component has a finite reciprocal (a denormal component's is inf, whose products the
// shared kernel orders by its own rules; it keeps those rays).
inline bool eligible(const VoxelWorld& world, const Ray& ray) {
    if (!world.emptySpaceCurrent()) return false;
    // 1 / d overflows exactly for 0 < |d| <= 2^-1024 (the next denormal up has a reciprocal
    // below DBL_MAX): compares instead of three divisions.
    constexpr double kSmallest = 0x1p-1024;
    const Vec3d& d = ray.direction;
    const auto finiteReciprocal = [](double c) { return c == 0.0 || std::abs(c) > kSmallest; };
    return finiteReciprocal(d.x) && finiteReciprocal(d.y) && finiteReciprocal(d.z);  // NaN: no
}

// voxelStart for an origin at least one voxel inside every face of the world (o in
// [1, size - 1] on each axis): the ray starts at t = 0 in the cell of its origin, so the slab
// clip has nothing to decide. With o >= 1 and a finite 1 / d, the world's near plane is at a t
// strictly below zero on every moving axis (no underflow to -0, which voxelStart would count as
// an entry from outside), and the far one strictly above.
inline bool deepInside(const shared::VoxelWalk& w) {
    return w.o.x >= 1.0 && w.o.y >= 1.0 && w.o.z >= 1.0 && w.o.x <= w.size.x - 1.0 &&
           w.o.y <= w.size.y - 1.0 && w.o.z <= w.size.z - 1.0;
}

inline void startDeepInside(shared::VoxelWalk& w) {
    double best = -kInf;
    w.axis = -1;
    for (int a = 0; a < 3; ++a) {
        w.stp[a] = w.d[a] > 0.0 ? 1 : (w.d[a] < 0.0 ? -1 : 0);
        int f = shared::voxelFloorToInt(w.o[a]);
        // On a boundary and moving down: the ray is in the lower cell straight away.
        if (w.o[a] == double(f) && w.stp[a] < 0) f -= 1;
        w.cell[a] = f;
        if (w.stp[a] == 0) {
            w.next[a] = kInf;
            continue;
        }
        // The face the origin lies on (t == 0), if any: the largest entry t, highest axis on ties.
        const double te = shared::voxelExitT(f, -w.stp[a], w.o[a], w.inv[a]);
        if (te >= best) {
            best = te;
            w.axis = a;
        }
        w.next[a] = shared::voxelExitT(f, w.stp[a], w.o[a], w.inv[a]);
    }
    if (!(best >= 0.0)) w.axis = -1;
    w.t = 0.0;
}

// voxelStart's answer alone, without the start cell: whether the ray meets the world before tMax
// (its slab clip and miss test, the same operations in the same order). A ray of a camera tile
// whose frustum holds no solid voxel ends there: its walk would be one jump out of the world
// (docs/algorithms/voxel-traversal.md §4.6 "Clear tiles").
inline bool entersWorld(const Ray& ray, const Int3& size, double tMax) {
    double tEnter = -kInf, tExit = kInf;
    for (int a = 0; a < 3; ++a) {
        const double o = ray.origin[a], d = ray.direction[a];
        if (d == 0.0) {
            if (!(o >= 0.0 && o < double(size[a]))) return false;
            continue;
        }
        const double inv = 1.0 / d;
        double t0 = (0.0 - o) * inv, t1 = (double(size[a]) - o) * inv;
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
    }
    const double t0 = std::max(tEnter, 0.0);
    return !(tEnter > tExit || tExit < t0 || (tExit == t0 && tEnter < t0) || t0 > tMax);
}

// traverse's loop from the walk state `w` (voxelStart's, or the state after a skip's jump) with
// `steps` iterations already counted.
[[gnu::always_inline]] inline shared::VoxelTrace walkFrom(const VoxelWorld& world,
                                                          const shared::VoxelWalk& w, double tMax,
                                                          int cap, int steps) {
    const Int3 size = world.size();
    Axis x{w.o.x, w.d.x, w.inv.x, w.stp[0], size.x, w.cell.x, w.next[0]};
    Axis y{w.o.y, w.d.y, w.inv.y, w.stp[1], size.y, w.cell.y, w.next[1]};
    Axis z{w.o.z, w.d.z, w.inv.z, w.stp[2], size.z, w.cell.z, w.next[2]};
    double t = w.t;
    int axis = w.axis;

    // t <= tLimit: t is finite and within tMax.
    const double tLimit = std::min(tMax, std::numeric_limits<double>::max());
    const auto miss = [&](bool capped) { return shared::voxelMiss(steps, capped); };
    const auto outside = [&] {
        return static_cast<unsigned>(x.cell) >= static_cast<unsigned>(x.size) ||
               static_cast<unsigned>(y.cell) >= static_cast<unsigned>(y.size) ||
               static_cast<unsigned>(z.cell) >= static_cast<unsigned>(z.size);
    };
    constexpr int kShift = VoxelWorld::kBrickShift;
    // The reach plane of the ray's octant (a zero component counts as positive, as in the
    // shared kernel).
    const Int3 bricks = world.brickCount();
    const std::size_t brickTotal = static_cast<std::size_t>(bricks.x) * bricks.y * bricks.z;
    const std::uint8_t* reach =
        world.brickReachData() + brickTotal * VoxelWorld::octantOf(x.stp < 0, y.stp < 0, z.stp < 0);
    for (;;) {
        if (steps >= cap) return miss(true);
        ++steps;
        const int bx = x.cell >> kShift, by = y.cell >> kShift, bz = z.cell >> kShift;
        const std::uint64_t mask = world.brickMask(bx, by, bz);
        if (mask != 0) {
            // Voxels of this brick, one A&W step each, until one is solid or the walk leaves the
            // brick (the mask and the cell's bit stay in registers meanwhile).
            int bit = VoxelWorld::brickBit(x.cell, y.cell, z.cell);
            for (;;) {
                if ((mask >> bit) & 1u) {
                    return shared::VoxelTrace(true, false, shared::ivec3(x.cell, y.cell, z.cell), t,
                                              axis, shared::ivec3(x.stp, y.stp, z.stp), steps);
                }
                // One A&W step (voxelStepOne): the smallest next boundary, lowest axis on ties.
                // Branches, not selects: along a ray the axis pattern is regular enough to
                // predict, and a predicted branch does not wait for the comparison. One
                // comparison ends the walk at an infinite boundary (no axis left to step) or
                // past tMax.
                const auto step = [&](Axis& s, int a, int bitStride) {
                    t = s.next;
                    axis = a;
                    s.cell += s.stp;
                    if (!(t <= tLimit) ||
                        static_cast<unsigned>(s.cell) >= static_cast<unsigned>(s.size)) {
                        return -1;
                    }
                    s.next = s.exitAt(s.cell);
                    bit += s.stp * bitStride;
                    constexpr int kLast = VoxelWorld::kBrickSide - 1;
                    return (s.cell & kLast) == (s.up ? 0 : kLast) ? 0 : 1;
                };
                int stayed;
                if (x.next <= y.next ? x.next <= z.next : false) {
                    stayed = step(x, 0, 1);
                } else if (!(x.next <= y.next) && y.next <= z.next) {
                    stayed = step(y, 1, 4);
                } else {
                    stayed = step(z, 2, 16);
                }
                if (stayed < 0) return miss(false);
                if (stayed == 0) break;  // into another brick: the outer loop reads its mask
                // The loop head again, for a cell of the same brick.
                if (steps >= cap) return miss(true);
                ++steps;
            }
            continue;
        }
        // An empty brick: leave the empty cube of bricks from it towards the ray's octant
        // (voxelLeaveBox).
        const int r = reach[(static_cast<std::size_t>(bz) * bricks.y + by) * bricks.x + bx] - 1;
        const auto lo = [&](const Axis& s, int b) {
            return s.stp < 0 ? std::max((b - r) << kShift, 0) : b << kShift;
        };
        const auto hi = [&](const Axis& s, int b) {
            return std::min((s.stp < 0 ? b + 1 : b + r + 1) << kShift, s.size) - 1;
        };
        const int lx = lo(x, bx), ly = lo(y, by), lz = lo(z, bz);
        const int hx = hi(x, bx), hy = hi(y, by), hz = hi(z, bz);
        const double tx = x.stp != 0 ? x.exitAt(x.stp > 0 ? hx : lx) : kInf;
        const double ty = y.stp != 0 ? y.exitAt(y.stp > 0 ? hy : ly) : kInf;
        const double tz = z.stp != 0 ? z.exitAt(z.stp > 0 ? hz : lz) : kInf;
        int a = 0;
        double tJump = tx;
        if (ty < tJump) a = 1, tJump = ty;
        if (tz < tJump) a = 2, tJump = tz;
        if (tJump == kInf) return miss(false);
        // A crossing axis other than a: the first cell whose exit the per-voxel loop has not yet
        // taken when it steps axis a at tJump (taken: earlier, or tied and a lower axis).
        const auto settle = [&](Axis& s, int boxLo, int boxHi, bool lowerThanA) {
            if (s.stp == 0) return;
            const auto taken = [&](double tc) { return tc < tJump || (tc == tJump && lowerThanA); };
            if (!taken(s.next)) return;
            const int first = s.cell, last = s.stp > 0 ? boxHi : boxLo;
            int c = first;
            double tc = s.next;
            if (std::abs(last - first) > LUXEL_VOXEL_SHORT_WALK) {
                // A long way to go: start at the floor of where the ray is, step back if that
                // overshot.
                c = shared::voxelFloorToInt(
                    std::clamp(s.o + tJump * s.d, -1.0, static_cast<double>(s.size + 1)));
                c = s.stp > 0 ? std::clamp(c, first, last) : std::clamp(c, last, first);
                while (c != first && !taken(s.exitAt(c - s.stp))) c -= s.stp;
                tc = s.exitAt(c);
            }
            while (c != last && taken(tc)) {
                c += s.stp;
                tc = s.exitAt(c);
            }
            s.cell = c;
            s.next = tc;
        };
        const auto cross = [&](Axis& s, int boxLo, int boxHi) {
            s.cell = s.stp > 0 ? boxHi + 1 : boxLo - 1;
        };
        if (a == 0) {
            settle(y, ly, hy, false);
            settle(z, lz, hz, false);
            cross(x, lx, hx);
        } else if (a == 1) {
            settle(x, lx, hx, true);
            settle(z, lz, hz, false);
            cross(y, ly, hy);
        } else {
            settle(x, lx, hx, true);
            settle(y, ly, hy, true);
            cross(z, lz, hz);
        }
        t = tJump;
        axis = a;
        if (outside() || t > tMax) return miss(false);
        if (a == 0) x.next = x.exitAt(x.cell);
        if (a == 1) y.next = y.exitAt(y.cell);
        if (a == 2) z.next = z.exitAt(z.cell);
    }
}

// The shared kernel's voxelTraverse(jumps = true, reachCurrent = true) for an eligible ray
// (finite, non-zero direction). With kSkip, the walk begins with a jump to a camera tile's skip
// plane (skip_jump.h, §4.6): the same result but for `steps`, which counts that jump as one.
template <bool kSkip = false>
inline shared::VoxelTrace traverse(const VoxelWorld& world, const Ray& ray, double tMax, int cap,
                                   stream::Skip skip = {}) {
    shared::VoxelWalk w;
    w.o = toShared(ray.origin);
    w.d = toShared(ray.direction);
    w.inv = shared::dvec3(1.0 / w.d.x, 1.0 / w.d.y, 1.0 / w.d.z);
    const Int3 size = world.size();
    w.size = shared::ivec3(size.x, size.y, size.z);
    if (deepInside(w)) {
        startDeepInside(w);
    } else if (!shared::voxelStart(w, tMax)) {
        return shared::voxelMiss(0, false);
    }
    int steps = 0;
    if constexpr (kSkip) {
        if (skip.axis >= 0) {
            const stream::SkipResult jumped = stream::jumpToPlane(w, skip, size, tMax);
            if (jumped == stream::SkipResult::Missed) return shared::voxelMiss(1, false);
            if (jumped == stream::SkipResult::Jumped) steps = 1;
        }
    }
    return walkFrom(world, w, tMax, cap, steps);
}

// voxelTraverse with jumps: the loop above for an eligible ray, the shared kernel for the others.
inline shared::VoxelTrace traverseAny(const VoxelWorld& world, const Ray& ray, double tMax,
                                      int cap) {
    if (eligible(world, ray)) return traverse(world, ray, tMax, cap);
    const Int3 size = world.size();
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    return shared::voxelTraverse(world, {size.x, size.y, size.z}, chunkShift, toShared(ray.origin),
                                 toShared(ray.direction), tMax, cap, true,
                                 world.emptySpaceCurrent());
}

}  // namespace luxel::voxel::fast
