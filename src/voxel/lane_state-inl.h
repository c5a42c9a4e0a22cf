// The SIMD lane walk's per-lane state (src/voxel/cast_stream.cpp): the fields of a lane, kept
// as arrays between refills, and a packet of lanes held in vectors while it steps. Per-target code
// (Highway): cast_stream.cpp includes it once for each target it compiles.
#if defined(LUXEL_VOXEL_LANE_STATE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef LUXEL_VOXEL_LANE_STATE_INL_H_
#undef LUXEL_VOXEL_LANE_STATE_INL_H_
#else
#define LUXEL_VOXEL_LANE_STATE_INL_H_
#endif

#include <cstddef>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace luxel::voxel::stream::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The most doubles a vector of any target holds.
constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);

// Lane state, as arrays between refills (one value per lane).
enum Field {
    kOx,
    kOy,
    kOz,
    kIx,
    kIy,
    kIz,
    kDx,
    kDy,
    kDz,
    kSx,
    kSy,
    kSz,
    kKx,
    kKy,
    kKz,
    kCx,
    kCy,
    kCz,
    kNx,
    kNy,
    kNz,
    kT,
    kAxis,
    kSteps,
    kRay,
    kPlane,  // byte offset of the reach plane of the ray's octant
    kFields
};

// A packet of lanes in vectors, one vector per field, and which lanes hold a ray.
template <class D>
struct Packet {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    V ox, oy, oz, ix, iy, iz, dx, dy, dz, sx, sy, sz, kx, ky, kz;
    V cx, cy, cz, nx, ny, nz, t, axis, steps, ray, plane;
    M active;
};

template <class D>
HWY_INLINE void LoadPacket(D d, double (&state)[kFields][kMaxLanes], Packet<D>& P) {
    P.ox = hn::Load(d, state[kOx]);
    P.oy = hn::Load(d, state[kOy]);
    P.oz = hn::Load(d, state[kOz]);
    P.ix = hn::Load(d, state[kIx]);
    P.iy = hn::Load(d, state[kIy]);
    P.iz = hn::Load(d, state[kIz]);
    P.dx = hn::Load(d, state[kDx]);
    P.dy = hn::Load(d, state[kDy]);
    P.dz = hn::Load(d, state[kDz]);
    P.sx = hn::Load(d, state[kSx]);
    P.sy = hn::Load(d, state[kSy]);
    P.sz = hn::Load(d, state[kSz]);
    P.kx = hn::Load(d, state[kKx]);
    P.ky = hn::Load(d, state[kKy]);
    P.kz = hn::Load(d, state[kKz]);
    P.cx = hn::Load(d, state[kCx]);
    P.cy = hn::Load(d, state[kCy]);
    P.cz = hn::Load(d, state[kCz]);
    P.nx = hn::Load(d, state[kNx]);
    P.ny = hn::Load(d, state[kNy]);
    P.nz = hn::Load(d, state[kNz]);
    P.t = hn::Load(d, state[kT]);
    P.axis = hn::Load(d, state[kAxis]);
    P.steps = hn::Load(d, state[kSteps]);
    P.ray = hn::Load(d, state[kRay]);
    P.plane = hn::Load(d, state[kPlane]);
    P.active = hn::Ge(P.ray, hn::Zero(d));
}

template <class D>
HWY_INLINE void StorePacket(D d, const Packet<D>& P, double (&state)[kFields][kMaxLanes]) {
    hn::Store(P.ox, d, state[kOx]);
    hn::Store(P.oy, d, state[kOy]);
    hn::Store(P.oz, d, state[kOz]);
    hn::Store(P.ix, d, state[kIx]);
    hn::Store(P.iy, d, state[kIy]);
    hn::Store(P.iz, d, state[kIz]);
    hn::Store(P.dx, d, state[kDx]);
    hn::Store(P.dy, d, state[kDy]);
    hn::Store(P.dz, d, state[kDz]);
    hn::Store(P.sx, d, state[kSx]);
    hn::Store(P.sy, d, state[kSy]);
    hn::Store(P.sz, d, state[kSz]);
    hn::Store(P.kx, d, state[kKx]);
    hn::Store(P.ky, d, state[kKy]);
    hn::Store(P.kz, d, state[kKz]);
    hn::Store(P.cx, d, state[kCx]);
    hn::Store(P.cy, d, state[kCy]);
    hn::Store(P.cz, d, state[kCz]);
    hn::Store(P.nx, d, state[kNx]);
    hn::Store(P.ny, d, state[kNy]);
    hn::Store(P.nz, d, state[kNz]);
    hn::Store(P.t, d, state[kT]);
    hn::Store(P.axis, d, state[kAxis]);
    hn::Store(P.steps, d, state[kSteps]);
    hn::Store(P.ray, d, state[kRay]);
    hn::Store(P.plane, d, state[kPlane]);
}

}  // namespace luxel::voxel::stream::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LUXEL_VOXEL_LANE_STATE_INL_H_
