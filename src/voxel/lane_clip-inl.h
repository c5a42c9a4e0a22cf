// voxelStart's slab clip (src/gpu/shaders/shared/voxel_walk.h) for a vector of rays, one per
// SIMD lane: the lane walk's start (lane_start-inl.h) and the camera sub-tiles' start
// (tile_start.cpp) both take it. Every operation is the scalar one on doubles, in the same order,
// so each lane's t and axis equal the one-ray start's bit for bit. Per-target code (Highway).
#if defined(LUXEL_VOXEL_LANE_CLIP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef LUXEL_VOXEL_LANE_CLIP_INL_H_
#undef LUXEL_VOXEL_LANE_CLIP_INL_H_
#else
#define LUXEL_VOXEL_LANE_CLIP_INL_H_
#endif

#include <limits>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace luxel::voxel::stream::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The world's box [0, sizes) clipped to each lane's ray (origin o, reciprocal direction inv):
// the largest entry t (tEnter, -inf where no axis enters), the axis it is on (the highest on
// ties; -1 for none) and the smallest exit t (tExit). A `flat` axis (a zero component, whose
// 1 / d is infinite) neither enters nor leaves.
template <class D>
HWY_INLINE void ClipToWorld(D d, const hn::Vec<D> (&o)[3], const hn::Vec<D> (&inv)[3],
                            const hn::Vec<D> (&sizes)[3], const hn::Mask<D> (&flat)[3],
                            hn::Vec<D>& tEnter, hn::Vec<D>& tExit, hn::Vec<D>& enterAxis) {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    const V zero = hn::Zero(d), inf = hn::Set(d, std::numeric_limits<double>::infinity());
    tEnter = hn::Neg(inf);
    tExit = inf;
    enterAxis = hn::Set(d, -1.0);
    for (int a = 0; a < 3; ++a) {
        V t0 = hn::Mul(hn::Sub(zero, o[a]), inv[a]);
        V t1 = hn::Mul(hn::Sub(sizes[a], o[a]), inv[a]);
        const M swap = hn::Gt(t0, t1);
        const V near = hn::IfThenElse(swap, t1, t0);
        t1 = hn::IfThenElse(swap, t0, t1);
        t0 = near;
        const M enter = hn::AndNot(flat[a], hn::Ge(t0, tEnter));
        tEnter = hn::IfThenElse(enter, t0, tEnter);
        enterAxis = hn::IfThenElse(enter, hn::Set(d, a), enterAxis);
        tExit = hn::IfThenElse(hn::AndNot(flat[a], hn::Lt(t1, tExit)), t1, tExit);
    }
}

}  // namespace luxel::voxel::stream::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LUXEL_VOXEL_LANE_CLIP_INL_H_
