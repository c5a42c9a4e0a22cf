// tileSkip: the frustum of a tile of camera rays walked slab by slab along its main axis, chunks
// first, then bricks, then cells; tileRays: the frustum's bounds, the tile's rays read once
// (docs/algorithms/voxel-traversal.md §4.6, "Starts in lanes").
#include "voxel/tile_frustum.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "voxel/brick_blocks.h"
#include "voxel/cast_stream.h"
#include "voxel/walk_access.h"

namespace luxel::voxel::stream {

namespace {

// The tile's frustum: origin o, main axis m moved along in direction sgn, and on the other axes
// the bounds [lo, hi] of the slopes d_a / |d_m| over the tile's rays. At distance u >= 0 in front
// of the origin along m, every ray lies within o_a + u * [lo_a, hi_a].
struct Frustum {
    double o[3];
    double lo[3], hi[3];
    // voxelRange's margin at distance u: marginAt0 + u * marginPerU.
    double marginAt0[3], marginPerU[3];
    int m, sgn;
};

// The most cells (chunks or bricks) one slab may test: a tile too wide for that stops the walk.
constexpr int kMaxSlabCells = 64;
// Slopes beyond this (a ray nearly parallel to the main axis's planes) give no skip.
constexpr double kMaxSlope = 1e6;

// The voxels [first, last] on axis a that the rays can touch between distances u0 and u1 along
// m, or false when they all lie outside the world there. The bounds are linear in u, so the ends
// bound the slab. The margin covers the rounding of these bounds and of the walk's own boundary
// t's, and the cells the walk visits where the ray touches their face (edge and corner ties).
bool voxelRange(const Frustum& f, int a, double u0, double u1, int size, int& first, int& last) {
    // 0 <= u0 <= u1: the lower bound is lo_a * u0 or lo_a * u1, whichever is smaller.
    const double lo = f.o[a] + (f.lo[a] >= 0.0 ? u0 : u1) * f.lo[a];
    const double hi = f.o[a] + (f.hi[a] >= 0.0 ? u1 : u0) * f.hi[a];
    const double margin = f.marginAt0[a] + u1 * f.marginPerU[a];
    const double from = lo - margin, to = hi + margin;
    if (!(to >= 0.0) || !(from < size)) return false;
    first = from <= 0.0 ? 0 : static_cast<int>(from);  // from > 0: truncation is floor
    last = to >= size ? size - 1 : static_cast<int>(to);
    return true;
}

// Whether every cell of side 2^shift (a chunk, a brick or a voxel) that the rays can touch in slab
// k along m (the cells k << shift .. on m) is empty: `empty(cell index on each axis)` tests a chunk
// or a brick; voxels are tested by the masks of the bricks they lie in.
template <typename Empty>
bool slabEmpty(const VoxelWorld& world, const Frustum& f, int shift, int k, Empty&& empty,
               int kEnd = -1) {
    const Int3 size = world.size();
    const int m = f.m;
    if (kEnd < k) kEnd = k;
    const double nearFace = k << shift;
    const double farFace = std::min((kEnd + 1) << shift, size[m]);
    // Distances along m of the slab's faces in front of the origin (the slab may hold it).
    const double uA = (f.sgn > 0 ? nearFace : farFace) - f.o[m];
    const double uB = (f.sgn > 0 ? farFace : nearFace) - f.o[m];
    const double u0 = std::max(0.0, uA * f.sgn), u1 = std::max(0.0, uB * f.sgn);
    int first[3], last[3];
    first[m] = k;
    last[m] = kEnd;
    int cells = 1;
    for (int a = 0; a < 3; ++a) {
        if (a == m) continue;
        if (!voxelRange(f, a, u0, u1, size[a], first[a], last[a])) return true;
        first[a] >>= shift;
        last[a] >>= shift;
        cells *= last[a] - first[a] + 1;
    }
    if (cells > kMaxSlabCells) return false;
    if (shift == 0) {
        // Cells: the box's cells of each brick it overlaps, tested by the brick's mask (k and
        // kEnd: the cell slabs k .. kEnd, one box for them all).
        constexpr int kB = VoxelWorld::kBrickShift, kLast = VoxelWorld::kBrickSide - 1;
        int lo[3], hi[3];
        const auto clip = [&](int a, int b) {
            lo[a] = std::max(b << kB, first[a]) & kLast;
            hi[a] = std::min(((b + 1) << kB) - 1, last[a]) & kLast;
        };
        for (int z = first[2] >> kB; z <= last[2] >> kB; ++z) {
            clip(2, z);
            for (int y = first[1] >> kB; y <= last[1] >> kB; ++y) {
                clip(1, y);
                for (int x = first[0] >> kB; x <= last[0] >> kB; ++x) {
                    clip(0, x);
                    if (world.brickMask(x, y, z) & blocks::boxBits(lo, hi)) return false;
                }
            }
        }
        return true;
    }
    for (int z = first[2]; z <= last[2]; ++z) {
        for (int y = first[1]; y <= last[1]; ++y) {
            for (int x = first[0]; x <= last[0]; ++x) {
                if (!empty(x, y, z)) return false;
            }
        }
    }
    return true;
}

// tileRays' pass over the rays for main axis M (a template argument: the components are named,
// not indexed at run time). Every test is folded into one flag without branches. The first ray's
// origin is finite, so an equal origin is too; a direction is finite with dm finite and non-zero
// in the rays' direction (0 < dm sgn <= DBL_MAX) and its slopes within the limit (an infinite or
// NaN component fails that).
template <int M>
bool readRays(std::span<const Ray> rays, int sgn, double (&lo)[3], double (&hi)[3]) {
    constexpr int a1 = M == 0 ? 1 : 0, a2 = M == 2 ? 1 : 2;
    const Vec3d o = rays.front().origin;
    const double s = sgn;
    double lo1 = kInfinity, hi1 = -kInfinity, lo2 = kInfinity, hi2 = -kInfinity;
    bool ok = true;
    for (const Ray& r : rays) {
        // The rays a tile further on (callers pass consecutive tiles of one array): read here
        // first, the rays come from memory, and this loop leaves too few loads in flight to
        // hide it (docs/algorithms/voxel-traversal.md §4.6, "Starts in lanes"). A prefetch past
        // the array's end is harmless.
        __builtin_prefetch(reinterpret_cast<const void*>(reinterpret_cast<std::uintptr_t>(&r) +
                                                         kCameraTileRays * sizeof(Ray)));
        const Vec3d& d = r.direction;
        const double dm = M == 0 ? d.x : (M == 1 ? d.y : d.z);
        const double d1 = a1 == 0 ? d.x : d.y;
        const double d2 = a2 == 1 ? d.y : d.z;
        const double along = dm * s;
        // One division per ray: d_a * (1 / |d_m|) lies within a few ulps of d_a / |d_m|, far
        // inside voxelRange's margin.
        const double perM = 1.0 / along;
        const double s1 = d1 * perM, s2 = d2 * perM;
        ok &= (r.origin.x == o.x) & (r.origin.y == o.y) & (r.origin.z == o.z);
        ok &= (along > 0.0) & (along <= std::numeric_limits<double>::max());
        ok &= (std::abs(s1) <= kMaxSlope) & (std::abs(s2) <= kMaxSlope);
        lo1 = std::min(lo1, s1);
        hi1 = std::max(hi1, s1);
        lo2 = std::min(lo2, s2);
        hi2 = std::max(hi2, s2);
    }
    lo[a1] = lo1;
    hi[a1] = hi1;
    lo[a2] = lo2;
    hi[a2] = hi2;
    return ok;
}

}  // namespace

TileRays tileRays(std::span<const Ray> rays, int m, int sgn) {
    TileRays t;
    if (rays.empty()) return t;
    const Ray& first = rays.front();
    if (!finiteRay(first)) return t;
    const Vec3d& d0 = first.direction;
    if (m < 0) {
        m = mainAxis(d0);
        sgn = d0[m] > 0.0 ? 1 : -1;
    }
    t.m = m;
    t.sgn = sgn;
    const bool ok = m == 0   ? readRays<0>(rays, sgn, t.lo, t.hi)
                    : m == 1 ? readRays<1>(rays, sgn, t.lo, t.hi)
                             : readRays<2>(rays, sgn, t.lo, t.hi);
    if (!ok) return t;
    t.ok = true;
    for (int a = 0; a < 3; ++a) t.o[a] = first.origin[a];
    return t;
}

TileRays mergeTileRays(const TileRays& a, const TileRays& b) {
    TileRays t = a;
    if (!a.ok || !b.ok || a.m != b.m || a.sgn != b.sgn || !(a.o[0] == b.o[0]) ||
        !(a.o[1] == b.o[1]) || !(a.o[2] == b.o[2])) {
        t.ok = false;
        return t;
    }
    for (int k = 0; k < 3; ++k) {
        t.lo[k] = std::min(a.lo[k], b.lo[k]);
        t.hi[k] = std::max(a.hi[k], b.hi[k]);
    }
    return t;
}

Skip tileSkip(const VoxelWorld& world, std::span<const Ray> tile, Skip from) {
    return tileSkip(world, tileRays(tile), from);
}

Skip tileSkip(const VoxelWorld& world, const TileRays& rays, Skip from) {
    if (!rays.ok || !world.emptySpaceCurrent()) return {};
    Frustum f;
    f.m = rays.m;
    f.sgn = rays.sgn;
    for (int a = 0; a < 3; ++a) {
        f.o[a] = rays.o[a];
        f.lo[a] = rays.lo[a];
        f.hi[a] = rays.hi[a];
    }

    for (int a = 0; a < 3; ++a) {
        const double slope = std::max(std::abs(f.lo[a]), std::abs(f.hi[a]));
        f.marginAt0[a] = 1e-3 + 1e-9 * std::abs(f.o[a]);
        f.marginPerU[a] = 1e-9 * (1.0 + slope);
    }
    const Int3 size = world.size();
    const int m = f.m, sizeM = size[m];
    const double om = f.o[m];
    // The rays never meet the world's span on m.
    if (f.sgn > 0 ? om >= sizeM : om <= 0.0) return {};
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    constexpr int kBrickShift = VoxelWorld::kBrickShift;
    const int chunksM = world.chunkCount()[m];
    const int bricksM = world.brickCount()[m];
    const auto chunkEmpty = [&](int x, int y, int z) {
        return world.chunkSolidCount(x, y, z) == 0;
    };
    const auto brickEmpty = [&](int x, int y, int z) { return world.brickMask(x, y, z) == 0; };
    // The slab holding the origin, or the world's near face (slabs in front of the origin only).
    // From an origin inside the world the first slab's box begins at the origin's point, so a
    // solid voxel in the origin's own brick ends the walk at a plane behind it: no skip.
    int originCell = static_cast<int>(std::floor(std::clamp(om, 0.0, sizeM - 0.5)));
    // From an enclosing tile's plane: its first cell slab (the rays' main axis is that tile's).
    if (from.axis == m) originCell = f.sgn > 0 ? from.plane : from.plane - 1;
    const int firstBrick = originCell >> kBrickShift;
    int plane = f.sgn > 0 ? sizeM : 0;  // no solid cell before the world's far face
    bool found = false;
    for (int kc = originCell >> chunkShift; !found && kc >= 0 && kc < chunksM; kc += f.sgn) {
        if (slabEmpty(world, f, chunkShift, kc, chunkEmpty)) continue;
        // Some chunk there holds a solid voxel: the bricks of this chunk slab, in travel order.
        const int perChunk = 1 << (chunkShift - kBrickShift);
        int kb = f.sgn > 0 ? kc * perChunk : std::min((kc + 1) * perChunk, bricksM) - 1;
        const int kbEnd = f.sgn > 0 ? std::min((kc + 1) * perChunk, bricksM) : kc * perChunk - 1;
        if (f.sgn > 0 ? kb < firstBrick : kb > firstBrick) kb = firstBrick;
        for (; !found && kb != kbEnd; kb += f.sgn) {
            if (slabEmpty(world, f, kBrickShift, kb, brickEmpty)) continue;
            // Some brick there holds a solid voxel: the cell slabs of this brick slab, in travel
            // order; the near face of the first that holds one in the box ends the walk. The
            // cells' own boxes are tighter than the brick slab's: where all are empty, the walk
            // goes on with the next brick slab.
            int kv = f.sgn > 0 ? kb << kBrickShift : std::min((kb + 1) << kBrickShift, sizeM) - 1;
            const int kvEnd =
                f.sgn > 0 ? std::min((kb + 1) << kBrickShift, sizeM) : (kb << kBrickShift) - 1;
            if (f.sgn > 0 ? kv < originCell : kv > originCell) kv = originCell;
            // Its cells ahead in one box first: where they are all empty, so is each cell slab.
            const int kvLast = kvEnd - f.sgn;
            if (kv != kvLast &&
                slabEmpty(world, f, 0, std::min(kv, kvLast), brickEmpty, std::max(kv, kvLast))) {
                continue;
            }
            for (; kv != kvEnd; kv += f.sgn) {
                if (slabEmpty(world, f, 0, kv, brickEmpty)) continue;
                plane = f.sgn > 0 ? kv : kv + 1;
                found = true;
                break;
            }
        }
    }
    // No plane in front of where the rays enter the world's span on m: nothing to skip.
    if (f.sgn > 0 ? plane <= std::max(om, 0.0) : plane >= std::min(om, double(sizeM))) return {};
    return {m, plane, !found};
}

}  // namespace luxel::voxel::stream
