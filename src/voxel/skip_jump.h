// A ray's walk begun at a tile's skip plane (tile_frustum.h): one jump from the walk's start
// state, exactly as the walk leaves an empty box (docs/algorithms/voxel-traversal.md §3.2 and
// §4.6). The box is the world on the other axes and, on the skip axis, the cells from the start
// cell up to the plane; the tile's frustum walk found every cell the ray visits in it empty, so
// the ray's state after the jump is the per-voxel loop's where it crosses the plane (or leaves
// the world), and every later visit, the hit, its t and its face are castRay's.
#pragma once

#include <algorithm>
#include <limits>

#include "voxel/tile_frustum.h"
#include "voxel/walk_access.h"

namespace luxel::voxel::stream {

enum class SkipResult { NotTaken, Jumped, Missed };

// The jump to `skip.plane` on `skip.axis` from the walk state `s` (voxelStart's; updated when
// Jumped, s.size unused). NotTaken where the start cell already lies at or past the plane; Missed
// where the ray leaves the world or passes tMax before it.
inline SkipResult jumpToPlane(gpu::shared::VoxelWalk& s, Skip skip, const Int3& size, double tMax) {
    const int m = skip.axis;
    if (s.stp[m] == 0) return SkipResult::NotTaken;
    int lo[3] = {0, 0, 0}, hi[3] = {size.x - 1, size.y - 1, size.z - 1};
    if (s.stp[m] > 0) {
        if (s.cell[m] >= skip.plane) return SkipResult::NotTaken;
        hi[m] = skip.plane - 1;
    } else {
        if (s.cell[m] < skip.plane) return SkipResult::NotTaken;
        lo[m] = skip.plane;
    }
    // voxelExitT: the one boundary formula, (cell + [step > 0] - o) * (1 / d).
    const auto exitAt = [&](int a, int c) {
        return (double(c + (s.stp[a] > 0 ? 1 : 0)) - s.o[a]) * s.inv[a];
    };
    // The exit axis: the first box plane crossed, lowest axis on ties.
    int a = -1;
    double tJump = std::numeric_limits<double>::infinity();
    for (int b = 0; b < 3; ++b) {
        if (s.stp[b] == 0) continue;
        const double tb = exitAt(b, s.stp[b] > 0 ? hi[b] : lo[b]);
        if (a < 0 || tb < tJump) a = b, tJump = tb;
    }
    // The other axes: the first cell whose exit the per-voxel loop has not yet taken at tJump
    // (taken: earlier, or tied and a lower axis), found from floor(o + t d) and corrected by the
    // exit test (the exits are monotone in the cell), never behind the current cell.
    for (int b = 0; b < 3; ++b) {
        if (b == a || s.stp[b] == 0) continue;
        const auto taken = [&](double tc) { return tc < tJump || (tc == tJump && b < a); };
        if (!taken(s.next[b])) continue;
        const int stp = s.stp[b], first = s.cell[b], last = stp > 0 ? hi[b] : lo[b];
        int c = gpu::shared::voxelFloorToInt(
            std::clamp(s.o[b] + tJump * s.d[b], -1.0, static_cast<double>(size[b] + 1)));
        c = stp > 0 ? std::clamp(c, first, last) : std::clamp(c, last, first);
        while (c != first && !taken(exitAt(b, c - stp))) c -= stp;
        double tc = exitAt(b, c);
        while (c != last && taken(tc)) {
            c += stp;
            tc = exitAt(b, c);
        }
        s.cell[b] = c;
        s.next[b] = tc;
    }
    s.cell[a] = s.stp[a] > 0 ? hi[a] + 1 : lo[a] - 1;
    s.t = tJump;
    s.axis = a;
    const bool outside = static_cast<unsigned>(s.cell[a]) >= static_cast<unsigned>(size[a]);
    if (outside || tJump > tMax) return SkipResult::Missed;
    s.next[a] = exitAt(a, s.cell[a]);
    return SkipResult::Jumped;
}

}  // namespace luxel::voxel::stream
