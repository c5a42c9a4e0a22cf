// Amanatides & Woo (1987) traversal with exact empty-chunk jumps; conventions in dda.h.
#include "luxel/voxel/dda.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace luxel::voxel {
namespace {

bool finite(const Vec3d& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// t at which the ray leaves `cell` on one axis. The single formula used for every boundary, so a
// boundary's t is bit-identical however the traversal reached it (plain steps or a chunk jump).
double exitT(int cell, int step, double origin, double direction) {
    return (static_cast<double>(cell + (step > 0 ? 1 : 0)) - origin) / direction;
}

// Position inside the voxel on one axis, in [0, 1).
float fraction(double p, int cell) {
    const float f = static_cast<float>(p - static_cast<double>(cell));
    return std::clamp(f, 0.0f, std::nextafter(1.0f, 0.0f));
}

Hit makeHit(const Ray& ray, Int3 cell, double t, int axis, const int step[3], int steps) {
    Hit hit;
    hit.hit = true;
    hit.voxel = cell;
    hit.t = t;
    hit.steps = steps;
    for (int a = 0; a < 3; ++a) {
        const double p = t == 0.0 ? ray.origin[a] : ray.origin[a] + t * ray.direction[a];
        hit.point[a] = std::clamp(p, static_cast<double>(cell[a]), cell[a] + 1.0);
    }
    if (axis >= 0) {
        hit.normal[axis] = -step[axis];
        // Snap onto the entry plane so secondary rays start exactly on the face.
        hit.point[axis] = static_cast<double>(cell[axis] + (step[axis] > 0 ? 0 : 1));
    }
    // Face UVs as in the seed (ChunkTracer4 RayMarch): x faces (z, y), z faces (x, y), y faces and
    // origins inside a voxel (x, z).
    int uAxis = 0, vAxis = 2;
    if (axis == 0) uAxis = 2, vAxis = 1;
    if (axis == 2) uAxis = 0, vAxis = 1;
    hit.u = fraction(hit.point[uAxis], cell[uAxis]);
    hit.v = fraction(hit.point[vAxis], cell[vAxis]);
    return hit;
}

}  // namespace

Hit castRay(const VoxelWorld& world, const Ray& ray, double tMax, int stepCap, ChunkSkip skip) {
    Hit miss;
    const Vec3d& o = ray.origin;
    const Vec3d& d = ray.direction;
    const Int3 size = world.size();
    if (!finite(o) || !finite(d) || (d.x == 0.0 && d.y == 0.0 && d.z == 0.0) || !(tMax >= 0.0)) {
        return miss;
    }
    const int cap = stepCap > 0 ? stepCap : 3 * (size.x + size.y + size.z);

    // Slab test against [0, size]. A zero component (either sign) constrains nothing but the
    // origin: the ray belongs to the cells floor(o), which must exist. Ties on entry keep the
    // highest axis (the plane crossed last under the x-then-y-then-z step order).
    double tEnter = -kInfinity, tExit = kInfinity;
    int enterAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (!(o[a] >= 0.0 && o[a] < size[a])) return miss;
            continue;
        }
        double t0 = (0.0 - o[a]) / d[a];
        double t1 = (static_cast<double>(size[a]) - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 >= tEnter) tEnter = t0, enterAxis = a;
        tExit = std::min(tExit, t1);
    }
    const double t0 = std::max(tEnter, 0.0);
    // Miss: the box is behind or beside the ray, or the origin is on its boundary moving out.
    // A ray grazing an edge from outside (tEnter == tExit > 0) touches it and counts.
    if (tEnter > tExit || tExit < t0 || (tExit == t0 && tEnter < t0) || t0 > tMax) return miss;

    int step[3];
    Int3 cell;
    const bool fromOutside = tEnter >= 0.0;
    for (int a = 0; a < 3; ++a) {
        step[a] = d[a] > 0.0 ? 1 : (d[a] < 0.0 ? -1 : 0);
        if (fromOutside && a == enterAxis) {
            cell[a] = step[a] > 0 ? 0 : size[a] - 1;
            continue;
        }
        const double p = t0 == 0.0 ? o[a] : o[a] + t0 * d[a];
        double f = std::floor(p);
        // On a boundary and moving down: the ray is in the lower cell straight away.
        if (p == f && step[a] < 0) f -= 1.0;
        cell[a] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(size[a] - 1)));
    }

    // The face the first cell is entered through: the world face, or for an origin inside the
    // world the cell face the origin lies on (t == 0); none when strictly inside.
    int axis = -1;
    if (fromOutside) {
        axis = enterAxis;
    } else {
        double best = -kInfinity;
        for (int a = 0; a < 3; ++a) {
            if (step[a] == 0) continue;
            const double te = exitT(cell[a], -step[a], o[a], d[a]);
            if (te >= best) best = te, axis = a;
        }
        if (!(best >= 0.0)) axis = -1;  // -0.0 >= 0: an origin on the face counts
    }

    double next[3];
    for (int a = 0; a < 3; ++a)
        next[a] = step[a] != 0 ? exitT(cell[a], step[a], o[a], d[a]) : kInfinity;

    const auto missAfter = [&miss](int n) {
        miss.steps = n;
        return miss;
    };
    const int shift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    const bool skipping = skip == ChunkSkip::Enabled;
    double t = t0;
    int steps = 0;
    for (;;) {
        if (steps >= cap) {
            miss.capped = true;
            return missAfter(steps);
        }
        ++steps;
        if (skipping &&
            world.chunkSolidCount(cell.x >> shift, cell.y >> shift, cell.z >> shift) == 0) {
            // Jump to where the plain traversal leaves this (empty) chunk: the first chunk plane
            // crossed, lowest axis on ties, exactly as the per-voxel loop orders its steps.
            int a = -1;
            double tJump = kInfinity;
            int chunkLo[3], chunkHi[3];
            for (int b = 0; b < 3; ++b) {
                const int lo = (cell[b] >> shift) << shift;
                const int hi = std::min(lo + (1 << shift), size[b]) - 1;
                chunkLo[b] = lo, chunkHi[b] = hi;
                if (step[b] == 0) continue;
                const double tb = exitT(step[b] > 0 ? hi : lo, step[b], o[b], d[b]);
                if (tb < tJump) tJump = tb, a = b;
            }
            if (a < 0 || tJump == kInfinity) return missAfter(steps);
            // The other axes: the first cell whose exit the plain loop has not yet taken when it
            // steps axis a at tJump (crossed = earlier, or tied and a lower axis).
            for (int b = 0; b < 3; ++b) {
                if (b == a || step[b] == 0) continue;
                const auto crossed = [&](double tb) {
                    return tb < tJump || (tb == tJump && b < a);
                };
                const int first = cell[b], last = step[b] > 0 ? chunkHi[b] : chunkLo[b];
                const double p = o[b] + tJump * d[b];
                int c = static_cast<int>(std::clamp(std::floor(p), -1.0, size[b] + 1.0));
                c = step[b] > 0 ? std::clamp(c, first, last) : std::clamp(c, last, first);
                while (c != first && !crossed(exitT(c - step[b], step[b], o[b], d[b]))) {
                    c -= step[b];
                }
                while (c != last && crossed(exitT(c, step[b], o[b], d[b]))) c += step[b];
                cell[b] = c;
                next[b] = exitT(c, step[b], o[b], d[b]);
            }
            t = tJump;
            cell[a] = step[a] > 0 ? chunkHi[a] + 1 : chunkLo[a] - 1;
            axis = a;
            if (cell[a] < 0 || cell[a] >= size[a] || t > tMax) return missAfter(steps);
            next[a] = exitT(cell[a], step[a], o[a], d[a]);
            continue;
        }
        if (world.solid(cell.x, cell.y, cell.z)) return makeHit(ray, cell, t, axis, step, steps);
        // Strict order x, y, z on ties (Amanatides & Woo's comparison chain).
        const int a =
            next[0] <= next[1] ? (next[0] <= next[2] ? 0 : 2) : (next[1] <= next[2] ? 1 : 2);
        if (next[a] == kInfinity) return missAfter(steps);
        t = next[a];
        cell[a] += step[a];
        axis = a;
        if (cell[a] < 0 || cell[a] >= size[a] || t > tMax) return missAfter(steps);
        next[a] = exitT(cell[a], step[a], o[a], d[a]);
    }
}

}  // namespace luxel::voxel
