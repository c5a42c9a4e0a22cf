// Which rays take the SIMD lanes of the lane walk (src/voxel/cast_stream.cpp) and where each
// starts: rays from inside the world take the one-ray loop (Lanes::FromOutside), rays that end at
// the start are recorded at once, the rest get voxelStart for a vector of them at once. Per-target
// code (Highway): cast_stream.cpp includes it once for each target it compiles.
#if defined(LUXEL_VOXEL_LANE_START_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef LUXEL_VOXEL_LANE_START_INL_H_
#undef LUXEL_VOXEL_LANE_START_INL_H_
#else
#define LUXEL_VOXEL_LANE_START_INL_H_
#endif

#include <cstddef>
#include <cstdint>

#include <hwy/highway.h>

#include "voxel/cast_stream.h"
#include "voxel/fast_walk.h"
#include "voxel/lane_clip-inl.h"
#include "voxel/lane_state-inl.h"

HWY_BEFORE_NAMESPACE();
namespace luxel::voxel::stream::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// voxelStart for the next rays from rays[nextRay] on, a vector of them at once, into `pending`
// (lane arrays); returns how many it put there. Rays that end at the start (a miss, or rays the
// fast walk does not take) and rays the one-ray loop takes are recorded in `out` here.
template <class D>
HWY_INLINE std::size_t StartRays(D d, const Walk& walk, const Ray* rays, std::size_t count,
                                 std::size_t& nextRay, gpu::shared::VoxelTrace* out,
                                 double (&pending)[kFields][kMaxLanes]) {
    namespace shared = gpu::shared;
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    const std::size_t lanes = hn::Lanes(d);
    const VoxelWorld& world = *walk.world;
    const Int3 size = world.size();
    const Int3 bricks = world.brickCount();
    const std::int64_t brickTotal = std::int64_t{bricks.x} * bricks.y * bricks.z;
    const double tMax = walk.tMax;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), minusOne = hn::Set(d, -1.0);
    const V inf = hn::Set(d, fast::kInf), vtMax = hn::Set(d, tMax);
    const V sizeX = hn::Set(d, size.x), sizeY = hn::Set(d, size.y), sizeZ = hn::Set(d, size.z);
    HWY_ALIGN double ray[kFields][kMaxLanes] = {};
    std::size_t m = 0;
    while (m < lanes && nextRay < count) {
        const std::size_t i = nextRay++;
        const Ray& r = rays[i];
        if (!finiteRay(r) || !(tMax >= 0.0)) {
            out[i] = shared::voxelMiss(0, false);
            continue;
        }
        if (!fast::eligible(world, r)) {
            out[i] = fast::traverseAny(world, r, tMax, walk.cap);
            continue;
        }
        if (walk.lanes == Lanes::FromOutside && startsInside(world, r)) {
            out[i] = fast::traverse(world, r, tMax, walk.cap);
            continue;
        }
        for (int a = 0; a < 3; ++a) {
            ray[kOx + a][m] = r.origin[a];
            ray[kDx + a][m] = r.direction[a];
        }
        ray[kRay][m] = static_cast<double>(i);
        ++m;
    }
    for (std::size_t l = m; l < lanes; ++l) {  // unused lanes: a harmless ray, dropped below
        for (int a = 0; a < 3; ++a) {
            ray[kOx + a][l] = 0.5;
            ray[kDx + a][l] = 1.0;
        }
        ray[kRay][l] = -1.0;
    }
    const V sizes[3] = {sizeX, sizeY, sizeZ};
    V o[3], dir[3], inv[3];
    M flat[3];
    M reject = hn::Lt(hn::Load(d, ray[kRay]), zero);
    for (int a = 0; a < 3; ++a) {
        o[a] = hn::Load(d, ray[kOx + a]);
        dir[a] = hn::Load(d, ray[kDx + a]);
        inv[a] = hn::Div(one, dir[a]);
        flat[a] = hn::Eq(dir[a], zero);
        const M inside = hn::And(hn::Ge(o[a], zero), hn::Lt(o[a], sizes[a]));
        reject = hn::Or(reject, hn::AndNot(inside, flat[a]));
    }
    V tEnter, tExit, enterAxis;
    ClipToWorld(d, o, inv, sizes, flat, tEnter, tExit, enterAxis);
    const V t0 = hn::IfThenElse(hn::Lt(tEnter, zero), zero, tEnter);  // max(tEnter, 0)
    reject = hn::Or(reject, hn::Or(hn::Gt(tEnter, tExit), hn::Lt(tExit, t0)));
    reject = hn::Or(reject, hn::And(hn::Eq(tExit, t0), hn::Lt(tEnter, t0)));
    reject = hn::Or(reject, hn::Gt(t0, vtMax));
    const M fromOutside = hn::Ge(tEnter, zero);
    const M atOrigin = hn::Eq(t0, zero);
    V cell[3], stp[3];
    for (int a = 0; a < 3; ++a) {
        const M up = hn::Gt(dir[a], zero), down = hn::Lt(dir[a], zero);
        stp[a] = hn::IfThenElse(up, one, hn::IfThenElseZero(down, minusOne));
        const V p = hn::IfThenElse(atOrigin, o[a], hn::Add(o[a], hn::Mul(t0, dir[a])));
        const V clamped =
            hn::IfThenElse(hn::Lt(sizes[a], hn::IfThenElse(hn::Lt(p, minusOne), minusOne, p)),
                           sizes[a], hn::IfThenElse(hn::Lt(p, minusOne), minusOne, p));
        V f = hn::Floor(clamped);
        f = hn::IfThenElse(hn::And(hn::Eq(p, f), down), hn::Sub(f, one), f);
        f = hn::Min(hn::Max(f, zero), hn::Sub(sizes[a], one));
        const M entered = hn::And(fromOutside, hn::Eq(enterAxis, hn::Set(d, a)));
        cell[a] = hn::IfThenElse(entered, hn::IfThenElse(up, zero, hn::Sub(sizes[a], one)), f);
    }
    // The face the first cell is entered through (voxelStart's rule).
    V best = hn::Neg(inf), inner = minusOne;
    for (int a = 0; a < 3; ++a) {
        const V k = hn::IfThenElseZero(hn::Lt(stp[a], zero), one);  // exitT(cell, -stp)
        const V te = hn::Mul(hn::Sub(hn::Add(cell[a], k), o[a]), inv[a]);
        const M better = hn::AndNot(flat[a], hn::Ge(te, best));
        best = hn::IfThenElse(better, te, best);
        inner = hn::IfThenElse(better, hn::Set(d, a), inner);
    }
    inner = hn::IfThenElse(hn::Ge(best, zero), inner, minusOne);
    hn::Store(hn::IfThenElse(fromOutside, enterAxis, inner), d, ray[kAxis]);
    hn::Store(t0, d, ray[kT]);
    // The reach plane of the ray's octant (VoxelWorld::octantOf; a zero component counts as
    // positive, as in the shared kernel).
    V octant = zero;
    for (int a = 0; a < 3; ++a) {
        octant =
            hn::Add(octant, hn::IfThenElseZero(hn::Lt(stp[a], zero), hn::Set(d, double(1 << a))));
    }
    hn::Store(hn::Mul(octant, hn::Set(d, static_cast<double>(brickTotal))), d, ray[kPlane]);
    for (int a = 0; a < 3; ++a) {
        const V k = hn::IfThenElseZero(hn::Gt(stp[a], zero), one);
        hn::Store(inv[a], d, ray[kIx + a]);
        hn::Store(stp[a], d, ray[kSx + a]);
        hn::Store(k, d, ray[kKx + a]);
        hn::Store(cell[a], d, ray[kCx + a]);
        hn::Store(hn::IfThenElse(flat[a], inf, hn::Mul(hn::Sub(hn::Add(cell[a], k), o[a]), inv[a])),
                  d, ray[kNx + a]);
    }
    HWY_ALIGN std::uint8_t rejected[8] = {};
    hn::StoreMaskBits(d, reject, rejected);
    std::size_t pendingCount = 0;
    for (std::size_t l = 0; l < m; ++l) {
        if ((rejected[l / 8] >> (l % 8)) & 1) {
            out[static_cast<std::size_t>(ray[kRay][l])] = shared::voxelMiss(0, false);
            continue;
        }
        for (int f = 0; f < kFields; ++f) pending[f][pendingCount] = ray[f][l];
        pending[kSteps][pendingCount] = 0.0;
        ++pendingCount;
    }
    return pendingCount;
}

}  // namespace luxel::voxel::stream::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LUXEL_VOXEL_LANE_START_INL_H_
