// beamLength and BeamScan: a run of parallel rays walked once, slab by slab along the main axis
// from the world's far face back towards the origins (docs/algorithms/voxel-traversal.md §4.7).
#include "voxel/parallel_beam.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "voxel/brick_blocks.h"
#include "voxel/fast_walk.h"
#include "voxel/tile_frustum.h"

namespace luxel::voxel::stream {

namespace {

// The beam: main axis m, moved along in direction sgn; across it, the ray through origin o is at
// c_a + s * q_a where s is the coordinate on m, q_a = d_a / d_m and c_a = o_a - o_m * q_a. The
// rays' c span [cLo, cHi] on each axis a != m.
struct Beam {
    int m, sgn;
    double q[3], cLo[3], cHi[3];
    double margin[3];  // voxelRange's
};

// The most cells (chunks or bricks) one slab may test: a slab box wider than that counts as
// holding a solid voxel (stopping the scan early is always safe).
constexpr int kMaxSlabCells = 64;

// The voxels [first, last] on axis a that the rays can touch between s0 and s1 on m (s0 < s1, both
// in [0, size on m]), or false when they all lie outside the world there. The bounds are linear in
// s, so the ends bound the slab. The margin covers the rounding of these bounds and of the walk's
// boundary t's, and the cells the walk visits where a ray only touches their face (edge and
// corner ties, and an origin on a cell plane moving down).
bool voxelRange(const Beam& b, int a, double s0, double s1, int size, int& first, int& last) {
    const double q = b.q[a];
    const double from = b.cLo[a] + (q >= 0.0 ? s0 : s1) * q - b.margin[a];
    const double to = b.cHi[a] + (q >= 0.0 ? s1 : s0) * q + b.margin[a];
    if (!(to >= 0.0) || !(from < size)) return false;
    first = from <= 0.0 ? 0 : static_cast<int>(from);
    last = to >= size ? size - 1 : static_cast<int>(to);
    return true;
}

// Whether the voxels [mFirst, mLast] on m (a chunk, brick or cell slab) hold no solid voxel where
// the rays can touch them: `empty(lo, hi)` tests the voxels [lo, hi] (inclusive, per axis) of one
// cell of side 2^shift (a chunk or a brick) that the box overlaps.
template <typename Empty>
bool slabEmpty(const Beam& b, const Int3& size, int mFirst, int mLast, int shift, Empty&& empty) {
    const int m = b.m;
    int first[3], last[3];
    first[m] = mFirst;
    last[m] = mLast;
    int cells = 1;
    for (int a = 0; a < 3; ++a) {
        if (a == m) continue;
        if (!voxelRange(b, a, mFirst, mLast + 1.0, size[a], first[a], last[a])) return true;
        cells *= (last[a] >> shift) - (first[a] >> shift) + 1;
    }
    if (cells > kMaxSlabCells) return false;
    int lo[3], hi[3];
    const auto clip = [&](int a, int c) {
        lo[a] = std::max(c << shift, first[a]);
        hi[a] = std::min(((c + 1) << shift) - 1, last[a]);
    };
    for (int z = first[2] >> shift; z <= last[2] >> shift; ++z) {
        clip(2, z);
        for (int y = first[1] >> shift; y <= last[1] >> shift; ++y) {
            clip(1, y);
            for (int x = first[0] >> shift; x <= last[0] >> shift; ++x) {
                clip(0, x);
                if (!empty(lo, hi)) return false;
            }
        }
    }
    return true;
}

}  // namespace

std::size_t beamLength(const VoxelWorld& world, std::span<const Ray> rays) {
    if (rays.empty()) return 0;
    const Ray& first = rays.front();
    if (!finiteRay(first) || !fast::eligible(world, first)) return 0;
    const Vec3d d = first.direction;
    const int m = mainAxis(d);
    double q[3], lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        q[a] = d[a] / d[m];
        lo[a] = hi[a] = first.origin[a] - first.origin[m] * q[a];
    }
    const std::size_t n = std::min(rays.size(), kBeamRays);
    std::size_t count = 1;
    for (; count < n; ++count) {
        const Ray& r = rays[count];
        if (!(r.direction == d)) break;
        const Vec3d& o = r.origin;
        if (!std::isfinite(o.x) || !std::isfinite(o.y) || !std::isfinite(o.z)) break;
        bool within = true;
        for (int a = 0; a < 3 && within; ++a) {
            if (a == m) continue;
            const double c = o[a] - o[m] * q[a];
            const double l = std::min(lo[a], c), h = std::max(hi[a], c);
            within = h - l <= kBeamWidth;
            lo[a] = l, hi[a] = h;
        }
        if (!within) break;
    }
    return count;
}

BeamScan::BeamScan(const VoxelWorld& world) : world_(world) {
    for (auto& axis : farChunk_) axis[0] = axis[1] = kUnknown;
}

int BeamScan::farChunk(int m, int sgn) {
    int& known = farChunk_[m][sgn > 0 ? 1 : 0];
    if (known != kUnknown) return known;
    const Int3 chunks = world_.chunkCount();
    const int u = m == 0 ? 1 : 0, v = m == 2 ? 1 : 2;
    known = sgn > 0 ? -1 : chunks[m];  // none: every slab is empty
    for (int k = sgn > 0 ? chunks[m] - 1 : 0; k >= 0 && k < chunks[m]; k -= sgn) {
        for (int i = 0; i < chunks[u] && known != k; ++i) {
            for (int j = 0; j < chunks[v]; ++j) {
                int c[3];
                c[m] = k, c[u] = i, c[v] = j;
                if (world_.chunkSolidCount(c[0], c[1], c[2]) != 0) {
                    known = k;
                    break;
                }
            }
        }
        if (known == k) break;
    }
    return known;
}

BeamLimit BeamScan::limit(std::span<const Ray> beam) {
    const VoxelWorld& world = world_;
    const Vec3d d = beam.front().direction;
    Beam b;
    b.m = mainAxis(d);
    b.sgn = d[b.m] > 0.0 ? 1 : -1;
    const int m = b.m;
    double oLo = kInfinity, oHi = -kInfinity;
    for (int a = 0; a < 3; ++a) {
        b.q[a] = a == m ? 0.0 : d[a] / d[m];
        b.cLo[a] = kInfinity;
        b.cHi[a] = -kInfinity;
    }
    for (const Ray& r : beam) {
        const Vec3d& o = r.origin;
        oLo = std::min(oLo, o[m]);
        oHi = std::max(oHi, o[m]);
        for (int a = 0; a < 3; ++a) {
            if (a == m) continue;
            const double c = o[a] - o[m] * b.q[a];
            b.cLo[a] = std::min(b.cLo[a], c);
            b.cHi[a] = std::max(b.cHi[a], c);
        }
    }
    const Int3 size = world.size();
    const int sizeM = size[m];
    for (int a = 0; a < 3; ++a) {
        const double c = std::max(std::abs(b.cLo[a]), std::abs(b.cHi[a]));
        b.margin[a] = 1e-3 + 1e-9 * (c + sizeM * (1.0 + std::abs(b.q[a])));
    }
    // The cell slab of the origin furthest back (an origin on a cell plane moving down starts in
    // the lower cell), clamped into the world: the scan ends there.
    const double back = b.sgn > 0 ? oLo : oHi;
    const double backCell = b.sgn > 0 ? std::floor(back) : std::ceil(back) - 1.0;
    const int lastCell = static_cast<int>(std::clamp(backCell, 0.0, sizeM - 1.0));
    const int chunkShift = std::countr_zero(static_cast<unsigned>(world.chunkSize()));
    constexpr int kBrickShift = VoxelWorld::kBrickShift;
    const auto chunkEmpty = [&](const int lo[3], const int hi[3]) {
        (void)hi;
        return world.chunkSolidCount(lo[0] >> chunkShift, lo[1] >> chunkShift,
                                     lo[2] >> chunkShift) == 0;
    };
    const auto brickEmpty = [&](const int lo[3], const int hi[3]) {
        (void)hi;
        return world.brickMask(lo[0] >> kBrickShift, lo[1] >> kBrickShift, lo[2] >> kBrickShift) ==
               0;
    };
    const auto cellsEmpty = [&](const int lo[3], const int hi[3]) {
        constexpr int kLast = VoxelWorld::kBrickSide - 1;
        const int l[3] = {lo[0] & kLast, lo[1] & kLast, lo[2] & kLast};
        const int h[3] = {hi[0] & kLast, hi[1] & kLast, hi[2] & kLast};
        const std::uint64_t mask =
            world.brickMask(lo[0] >> kBrickShift, lo[1] >> kBrickShift, lo[2] >> kBrickShift);
        return (mask & blocks::boxBits(l, h)) == 0;
    };
    // Slabs from the far face back to lastCell's: chunks, then the bricks of a chunk slab that
    // may hold a solid voxel, then the cells of such a brick slab. The first cell slab that may
    // hold one is the last the rays must walk through.
    const int lastBrick = lastCell >> kBrickShift, lastChunk = lastCell >> chunkShift;
    // Past the world's furthest chunk slab that holds a solid voxel, every slab is empty.
    const int farChunk = this->farChunk(m, b.sgn);
    if (b.sgn > 0 ? farChunk < lastChunk : farChunk > lastChunk) {
        return {m, b.sgn > 0 ? lastCell : lastCell + 1};
    }
    for (int kc = farChunk; kc != lastChunk - b.sgn; kc -= b.sgn) {
        const int c0 = kc << chunkShift, c1 = std::min((kc + 1) << chunkShift, sizeM) - 1;
        if (slabEmpty(b, size, c0, c1, chunkShift, chunkEmpty)) continue;
        const int perChunk = 1 << (chunkShift - kBrickShift);
        const int bricksM = world.brickCount()[m];
        const int kbFar = b.sgn > 0 ? std::min((kc + 1) * perChunk, bricksM) - 1 : kc * perChunk;
        const int kbNear = b.sgn > 0 ? std::max(kc * perChunk, lastBrick)
                                     : std::min((kc + 1) * perChunk - 1, lastBrick);
        for (int kb = kbFar; kb != kbNear - b.sgn; kb -= b.sgn) {
            const int b0 = kb << kBrickShift, b1 = std::min((kb + 1) << kBrickShift, sizeM) - 1;
            if (slabEmpty(b, size, b0, b1, kBrickShift, brickEmpty)) continue;
            const int kvFar =
                b.sgn > 0 ? std::min((kb + 1) << kBrickShift, sizeM) - 1 : kb << kBrickShift;
            const int kvNear = b.sgn > 0 ? std::max(kb << kBrickShift, lastCell)
                                         : std::min(((kb + 1) << kBrickShift) - 1, lastCell);
            for (int kv = kvFar; kv != kvNear - b.sgn; kv -= b.sgn) {
                if (slabEmpty(b, size, kv, kv, kBrickShift, cellsEmpty)) continue;
                return {m, b.sgn > 0 ? kv + 1 : kv};
            }
        }
    }
    // Nothing solid where the rays go: the plane at the back of the furthest-back origin's cell.
    return {m, b.sgn > 0 ? lastCell : lastCell + 1};
}

}  // namespace luxel::voxel::stream
