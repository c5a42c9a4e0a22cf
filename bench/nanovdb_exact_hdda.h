// An exact hierarchical DDA over a NanoVDB grid of binary voxels: a benchmark peer for luxel's
// traversals (bench/bench_octree.cpp), not luxel code.
//
// nanovdb::HDDA with the firstActive loop samples RoundDown(ray(hdda.time() + 1.0001)) after each
// node step: the cell it lands in is a guess near the node boundary, which for binary voxels
// misses or adds cells (75-86% pixel agreement with the exact voxel walk). This loop tracks the
// integer cell instead, as the per-voxel Amanatides & Woo walk does:
// - the boundary t of a cell on an axis is always (cell + (step > 0) - origin) / direction, the
//   formula of luxel's walk, so a boundary has one t however it was reached;
// - in a voxel of a leaf it takes one A&W step (ties: x, then y, then z);
// - in an inactive tile (or the background) of width `dim` (the accessor's getDim) it leaves the
//   box cell & ~(dim - 1) .. + dim - 1 in one jump: the first box plane crossed gives the new cell
//   on that axis, and on the others the entry point at that t is clamped into the box and
//   corrected by at most a cell, so ties fall as the per-voxel walk lets them fall;
// - an active voxel or an active tile (a uniform solid region after pruning) is a hit.
// The result is the per-voxel walk's first solid cell, hit for hit (checked in the benchmark).
#pragma once

#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/Ray.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"

namespace luxel::bench {

struct HddaHit {
    bool hit = false;
    Int3 voxel;
    double t = std::numeric_limits<double>::infinity();
    int steps = 0;  // voxel steps plus tile jumps
};

// The first active cell along the ray inside [0, size) (the grid's voxels in index space), with
// the start and tie conventions of voxel::castRay (include/luxel/voxel/dda.h).
template <typename GridT>
HddaHit castExactHdda(const GridT& grid, Int3 size, const voxel::Ray& ray) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    const int n[3] = {size.x, size.y, size.z};
    double inv[3], next[3];
    int stp[3], cell[3];
    double t0 = 0, t1 = kInf;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (!(o[a] >= 0 && o[a] < n[a])) return {};
            stp[a] = 0;
            inv[a] = kInf;
            continue;
        }
        stp[a] = d[a] > 0 ? 1 : -1;
        inv[a] = 1.0 / d[a];
        double lo = (0 - o[a]) * inv[a], hi = (n[a] - o[a]) * inv[a];
        if (lo > hi) std::swap(lo, hi);
        t0 = std::max(t0, lo);
        t1 = std::min(t1, hi);
    }
    if (!(t0 <= t1)) return {};
    auto exitT = [&](int a, int c) { return (c + (stp[a] > 0 ? 1 : 0) - o[a]) * inv[a]; };
    for (int a = 0; a < 3; ++a) {
        const double p = o[a] + t0 * d[a];
        int c = static_cast<int>(std::floor(p));
        if (stp[a] < 0 && c == p) --c;  // on a boundary moving down: the lower cell
        cell[a] = std::clamp(c, 0, n[a] - 1);
        next[a] = stp[a] != 0 ? exitT(a, cell[a]) : kInf;
    }
    double t = t0;
    auto acc = grid.getAccessor();
    const nanovdb::Ray<double> unused;  // getDim's ray argument is not read
    HddaHit out;
    const int cap = 3 * (n[0] + n[1] + n[2]);
    for (; out.steps < cap; ++out.steps) {
        const nanovdb::Coord ijk(cell[0], cell[1], cell[2]);
        if (acc.isActive(ijk)) {
            out.hit = true;
            out.voxel = {cell[0], cell[1], cell[2]};
            out.t = t;
            return out;
        }
        const int dim = static_cast<int>(acc.getDim(ijk, unused));
        int a;
        if (dim <= 1) {
            a = next[0] <= next[1] ? (next[0] <= next[2] ? 0 : 2) : (next[1] <= next[2] ? 1 : 2);
            if (next[a] == kInf) return out;
            t = next[a];
            cell[a] += stp[a];
        } else {
            int lo[3], hi[3];
            for (int b = 0; b < 3; ++b) {
                lo[b] = std::max(cell[b] & ~(dim - 1), 0);
                hi[b] = std::min((cell[b] & ~(dim - 1)) + dim - 1, n[b] - 1);
            }
            a = -1;
            double tJump = kInf;
            for (int b = 0; b < 3; ++b) {
                if (stp[b] == 0) continue;
                const double tb = exitT(b, stp[b] > 0 ? hi[b] : lo[b]);
                if (tb < tJump) {
                    tJump = tb;
                    a = b;
                }
            }
            if (a < 0) return out;
            for (int b = 0; b < 3; ++b) {
                if (b == a || stp[b] == 0) continue;
                // The per-voxel walk has left a cell at tJump when its exit is earlier, or tied
                // and on a lower axis (it steps x, then y, then z).
                auto crossed = [&](int c) {
                    const double tc = exitT(b, c);
                    return tc < tJump || (tc == tJump && b < a);
                };
                const int first = cell[b], last = stp[b] > 0 ? hi[b] : lo[b];
                const double p = o[b] + tJump * d[b];
                int c = static_cast<int>(std::floor(std::clamp(p, -1.0, n[b] + 1.0)));
                c = stp[b] > 0 ? std::clamp(c, first, last) : std::clamp(c, last, first);
                while (c != first && !crossed(c - stp[b])) c -= stp[b];
                while (c != last && crossed(c)) c += stp[b];
                cell[b] = c;
                next[b] = exitT(b, c);
            }
            t = tJump;
            cell[a] = stp[a] > 0 ? hi[a] + 1 : lo[a] - 1;
        }
        if (cell[a] < 0 || cell[a] >= n[a]) return out;
        next[a] = exitT(a, cell[a]);
    }
    return out;
}

}  // namespace luxel::bench
