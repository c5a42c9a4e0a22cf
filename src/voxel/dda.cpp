// Amanatides & Woo (1987) traversal with exact jumps over empty chunks and bricks; conventions in
// dda.h.
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
// boundary's t is bit-identical however the traversal reached it (plain steps or a block jump).
// A multiplication by the precomputed 1 / direction: a division's latency sits on the loop's
// critical path, and ties between axes with equal |direction| components stay exact either way.
double exitT(int cell, int step, double origin, double inverseDirection) {
    return (static_cast<double>(cell + (step > 0 ? 1 : 0)) - origin) * inverseDirection;
}

// floor for |x| well inside int range; std::floor is a library call on baseline x86-64 (no
// SSE4.1 round instruction) and dominated the cost of block jumps.
int floorToInt(double x) {
    const int i = static_cast<int>(x);  // truncates towards zero
    return i - (static_cast<double>(i) > x ? 1 : 0);
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
    // Face UVs as in the Unity voxel ray tracer (its ChunkTracer4 RayMarch): x faces (z, y), z
    // faces (x, y), y faces and origins inside a voxel (x, z).
    int uAxis = 0, vAxis = 2;
    if (axis == 0) uAxis = 2, vAxis = 1;
    if (axis == 2) uAxis = 0, vAxis = 1;
    hit.u = fraction(hit.point[uAxis], cell[uAxis]);
    hit.v = fraction(hit.point[vAxis], cell[vAxis]);
    return hit;
}

Hit capped(Hit miss, int steps) {
    miss.capped = true;
    miss.steps = steps;
    return miss;
}

// Box jumps find the cell on the other axes by stepping from the current one when the box is at
// most this many cells across (few crossings: cheaper than a floor and checks), else by floor.
constexpr int kShortWalk = 8;

// Traversal state of the per-voxel loop: the current cell, the t it was entered at and through
// which axis, and the t of the next boundary on each axis.
struct Walk {
    const Vec3d& o;
    const Vec3d& d;
    Vec3d inv;  // 1 / d (inf on zero components, which never step)
    Int3 size;
    int step[3];
    Int3 cell;
    double next[3];
    double t;
    int axis;

    double exitAt(int c, int a) const { return exitT(c, step[a], o[a], inv[a]); }

    // One A&W step; strict order x, y, z on ties (Amanatides & Woo's comparison chain). False when
    // the ray leaves the world or passes tMax.
    bool stepOne(double tMax) {
        const int a =
            next[0] <= next[1] ? (next[0] <= next[2] ? 0 : 2) : (next[1] <= next[2] ? 1 : 2);
        if (next[a] == kInfinity) return false;
        t = next[a];
        cell[a] += step[a];
        axis = a;
        if (cell[a] < 0 || cell[a] >= size[a] || t > tMax) return false;
        next[a] = exitAt(cell[a], a);
        return true;
    }

    // Jumps to the state the per-voxel loop reaches when it leaves the box of cells [lo, hi]
    // (which holds the current cell and no solid voxel): the first box plane crossed, lowest axis
    // on ties, exactly as stepOne orders its steps. False when that leaves the world or passes
    // tMax.
    bool leaveBox(const Int3& lo, const Int3& hi, double tMax) {
        int a = -1;
        double tJump = kInfinity;
        for (int b = 0; b < 3; ++b) {
            if (step[b] == 0) continue;
            const double tb = exitAt(step[b] > 0 ? hi[b] : lo[b], b);
            if (tb < tJump) tJump = tb, a = b;
        }
        if (a < 0 || tJump == kInfinity) return false;
        // The other axes: the first cell whose exit the plain loop has not yet taken when it
        // steps axis a at tJump (crossed = earlier, or tied and a lower axis).
        for (int b = 0; b < 3; ++b) {
            if (b == a || step[b] == 0) continue;
            const auto crossed = [&](double tb) { return tb < tJump || (tb == tJump && b < a); };
            const int first = cell[b], last = step[b] > 0 ? hi[b] : lo[b];
            int c = first;
            double tb = next[b];
            if (std::abs(last - first) > kShortWalk && crossed(tb)) {
                // A long way to go: start next to where the ray is at tJump, then correct.
                c = floorToInt(std::clamp(o[b] + tJump * d[b], -1.0, size[b] + 1.0));
                c = step[b] > 0 ? std::clamp(c, first, last) : std::clamp(c, last, first);
                while (c != first && !crossed(exitAt(c - step[b], b))) c -= step[b];
                tb = exitAt(c, b);
            }
            // Step on while the plain loop would already have left the cell.
            while (c != last && crossed(tb)) c += step[b], tb = exitAt(c, b);
            cell[b] = c;
            next[b] = tb;
        }
        t = tJump;
        cell[a] = step[a] > 0 ? hi[a] + 1 : lo[a] - 1;
        axis = a;
        if (cell[a] < 0 || cell[a] >= size[a] || t > tMax) return false;
        next[a] = exitAt(cell[a], a);
        return true;
    }
};

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
    // The world planes use the same formula as every cell boundary (the reciprocal): consistent t.
    const Vec3d inv{1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
    double tEnter = -kInfinity, tExit = kInfinity;
    int enterAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (!(o[a] >= 0.0 && o[a] < size[a])) return miss;
            continue;
        }
        double t0 = (0.0 - o[a]) * inv[a];
        double t1 = (static_cast<double>(size[a]) - o[a]) * inv[a];
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
        int f = floorToInt(std::clamp(p, -1.0, static_cast<double>(size[a])));
        // On a boundary and moving down: the ray is in the lower cell straight away.
        if (p == f && step[a] < 0) f -= 1;
        cell[a] = std::clamp(f, 0, size[a] - 1);
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
            const double te = exitT(cell[a], -step[a], o[a], inv[a]);
            if (te >= best) best = te, axis = a;
        }
        if (!(best >= 0.0)) axis = -1;  // -0.0 >= 0: an origin on the face counts
    }

    Walk w{o, d, inv, size, {step[0], step[1], step[2]}, cell, {}, t0, axis};
    for (int a = 0; a < 3; ++a) w.next[a] = step[a] != 0 ? w.exitAt(cell[a], a) : kInfinity;

    const auto missAfter = [&miss](int n) {
        miss.steps = n;
        return miss;
    };
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    constexpr int brickShift = VoxelWorld::kBrickShift;
    const bool distances = world.emptySpaceCurrent();
    int steps = 0;
    if (skip == ChunkSkip::Disabled) {
        for (;;) {
            if (steps >= cap) return capped(miss, steps);
            ++steps;
            if (world.solid(w.cell.x, w.cell.y, w.cell.z)) {
                return makeHit(ray, w.cell, w.t, w.axis, step, steps);
            }
            if (!w.stepOne(tMax)) return missAfter(steps);
        }
    }
    for (;;) {
        if (steps >= cap) return capped(miss, steps);
        ++steps;
        const Int3 c = w.cell;
        const std::uint64_t mask =
            world.brickMask(c.x >> brickShift, c.y >> brickShift, c.z >> brickShift);
        if (mask != 0) {
            if ((mask >> VoxelWorld::brickBit(c.x, c.y, c.z)) & 1u) {
                return makeHit(ray, c, w.t, w.axis, step, steps);
            }
            if (!w.stepOne(tMax)) return missAfter(steps);
            continue;
        }
        // An empty brick: leave the empty box of bricks around it when the distances are current,
        // else the whole chunk when it is empty, else just the brick.
        Int3 lo, hi;
        if (distances) {
            const Int3 b{c.x >> brickShift, c.y >> brickShift, c.z >> brickShift};
            const int r = world.brickDistance(b.x, b.y, b.z) - 1;
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::max((b[a] - r) << brickShift, 0);
                hi[a] = std::min((b[a] + r + 1) << brickShift, size[a]) - 1;
            }
        } else {
            const int shift =
                world.chunkSolidCount(c.x >> chunkShift, c.y >> chunkShift, c.z >> chunkShift) == 0
                    ? chunkShift
                    : brickShift;
            for (int a = 0; a < 3; ++a) {
                lo[a] = (c[a] >> shift) << shift;
                hi[a] = std::min(lo[a] + (1 << shift), size[a]) - 1;
            }
        }
        if (!w.leaveBox(lo, hi, tMax)) return missAfter(steps);
    }
}

}  // namespace luxel::voxel
