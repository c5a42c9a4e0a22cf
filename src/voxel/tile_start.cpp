// startAtPlane: voxelStart (src/gpu/shaders/shared/voxel_walk.h) and jumpToPlane
// (src/voxel/skip_jump.h) for a vector of a camera sub-tile's rays at once, one ray per SIMD lane
// (Highway, as src/voxel/cast_stream.cpp). Scalar, each ray's start is a chain of dependent
// divisions, products, floors and branches that the walk before and after it leaves little room
// to overlap; in lanes, several rays take it in one pass (docs/algorithms/voxel-traversal.md §4.6,
// "Starts in lanes"). Every operation is the scalar one on doubles (no fused multiply-add), in the
// same order, so each lane's state equals traverse<true>'s bit for bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "voxel/tile_start.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off
#include <hwy/highway.h>
// clang-format on

#include <cstddef>
#include <cstdint>

#include "voxel/lane_clip-inl.h"
#include "voxel/tile_start.h"

// The rays are read as six consecutive doubles each: origin, then direction.
static_assert(sizeof(luxel::voxel::Ray) == 6 * sizeof(double));

HWY_BEFORE_NAMESPACE();
namespace luxel::voxel::stream::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace shared = gpu::shared;

void StartAtPlane(const VoxelWorld& world, const Ray* rays, std::size_t count, Skip skip,
                  double tMax, shared::VoxelWalk* walks, PlaneStart* starts) {
    using D = hn::ScalableTag<double>;
    const D d;
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    const hn::RebindToSigned<D> di;
    const std::size_t lanes = hn::Lanes(d);
    constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
    const Int3 size = world.size();
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), minusOne = hn::Set(d, -1.0);
    const V vtMax = hn::Set(d, tMax);
    // 1 / d overflows for 0 < |d| <= 2^-1024 (fast::eligible): such lanes and zero components
    // are left to the one-ray walk.
    const V smallest = hn::Set(d, 0x1p-1024);
    const V sizes[3] = {hn::Set(d, size.x), hn::Set(d, size.y), hn::Set(d, size.z)};
    const int m = skip.axis;
    const V plane = hn::Set(d, skip.plane);

    for (std::size_t first = 0; first < count; first += lanes) {
        const std::size_t n = std::min(lanes, count - first);
        // The rays' components gathered straight into lanes (scalar stores read back as a
        // vector would stall on store forwarding); unused lanes repeat the last ray, dropped below.
        const auto lane = hn::Min(hn::Iota(di, 0), hn::Set(di, static_cast<std::int64_t>(n - 1)));
        const auto index = hn::Add(hn::ShiftLeft<2>(lane), hn::ShiftLeft<1>(lane));  // 6 lane
        const double* base = &rays[first].origin.x;
        V o[3], dir[3], inv[3];
        M oneRay = hn::Lt(zero, zero);
        for (int a = 0; a < 3; ++a) {
            o[a] = hn::GatherIndex(d, base + a, index);
            dir[a] = hn::GatherIndex(d, base + 3 + a, index);
            inv[a] = hn::Div(one, dir[a]);
            oneRay = hn::Or(oneRay, hn::Not(hn::Gt(hn::Abs(dir[a]), smallest)));
        }
        // voxelStart's slab clip (no zero components here: those lanes take the one-ray walk).
        const M none = hn::Lt(zero, zero);
        const M flat[3] = {none, none, none};
        V tEnter, tExit, enterAxis;
        ClipToWorld(d, o, inv, sizes, flat, tEnter, tExit, enterAxis);
        const V t0 = hn::IfThenElse(hn::Lt(tEnter, zero), zero, tEnter);  // max(tEnter, 0)
        M missed = hn::Or(hn::Gt(tEnter, tExit), hn::Lt(tExit, t0));
        missed = hn::Or(missed, hn::And(hn::Eq(tExit, t0), hn::Lt(tEnter, t0)));
        missed = hn::Or(missed, hn::Gt(t0, vtMax));
        // From inside the world the start takes another rule for its face: the one-ray walk.
        oneRay = hn::Or(oneRay, hn::AndNot(missed, hn::Lt(tEnter, zero)));
        const M atOrigin = hn::Eq(t0, zero);
        V cell[3], stp[3], k[3];
        M up[3];
        for (int a = 0; a < 3; ++a) {
            up[a] = hn::Gt(dir[a], zero);
            stp[a] = hn::IfThenElse(up[a], one, minusOne);
            k[a] = hn::IfThenElseZero(up[a], one);
            const V p = hn::IfThenElse(atOrigin, o[a], hn::Add(o[a], hn::Mul(t0, dir[a])));
            V c = hn::IfThenElse(hn::Lt(p, minusOne), minusOne, p);
            c = hn::IfThenElse(hn::Lt(sizes[a], c), sizes[a], c);
            V f = hn::Floor(c);
            f = hn::IfThenElse(hn::AndNot(up[a], hn::Eq(p, f)), hn::Sub(f, one), f);
            f = hn::Min(hn::Max(f, zero), hn::Sub(sizes[a], one));
            const M entered = hn::Eq(enterAxis, hn::Set(d, a));
            cell[a] = hn::IfThenElse(entered,
                                     hn::IfThenElseZero(hn::Not(up[a]), hn::Sub(sizes[a], one)), f);
        }
        // voxelExitT: (cell + [step > 0] - o) * (1 / d).
        const auto exitAt = [&](int a, V c) {
            return hn::Mul(hn::Sub(hn::Add(c, k[a]), o[a]), inv[a]);
        };
        V next[3];
        for (int a = 0; a < 3; ++a) next[a] = exitAt(a, cell[a]);

        // jumpToPlane: not taken where the start cell lies at or past the plane.
        const M notTaken = hn::Or(hn::And(up[m], hn::Ge(cell[m], plane)),
                                  hn::AndNot(up[m], hn::Lt(cell[m], plane)));
        // The box: the world, on m the cells up to the plane.
        V lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = zero;
            hi[a] = hn::Sub(sizes[a], one);
        }
        hi[m] = hn::IfThenElse(up[m], hn::Sub(plane, one), hi[m]);
        lo[m] = hn::IfThenElse(up[m], lo[m], plane);
        V bound[3];
        for (int a = 0; a < 3; ++a) bound[a] = hn::IfThenElse(up[a], hi[a], lo[a]);
        // The exit axis: the first box plane crossed, lowest axis on ties.
        V tJump = exitAt(0, bound[0]);
        const V ty = exitAt(1, bound[1]), tz = exitAt(2, bound[2]);
        const M pickY = hn::Lt(ty, tJump);
        tJump = hn::IfThenElse(pickY, ty, tJump);
        const M pickZ = hn::Lt(tz, tJump);
        tJump = hn::IfThenElse(pickZ, tz, tJump);
        const M sel[3] = {hn::Not(hn::Or(pickY, pickZ)), hn::AndNot(pickZ, pickY), pickZ};
        const M settleLanes = hn::Not(hn::Or(hn::Or(missed, oneRay), notTaken));
        // The other axes: the first cell whose exit the per-voxel loop has not yet taken at tJump
        // (taken: earlier, or tied and a lower axis than the exit axis), from floor(o + t d),
        // never behind the start cell.
        for (int b = 0; b < 3; ++b) {
            // b < a: a tie counts as taken.
            const M lower = b == 0 ? hn::Not(sel[0]) : (b == 1 ? sel[2] : hn::Lt(zero, zero));
            const auto taken = [&](V tc) {
                return hn::Or(hn::Lt(tc, tJump), hn::And(hn::Eq(tc, tJump), lower));
            };
            const M need = hn::And(hn::AndNot(sel[b], settleLanes), taken(next[b]));
            if (hn::AllFalse(d, need)) continue;
            const V firstCell = cell[b];
            const V last = hn::IfThenElse(up[b], hi[b], lo[b]);
            V g = hn::Add(o[b], hn::Mul(tJump, dir[b]));
            g = hn::IfThenElse(hn::Lt(g, minusOne), minusOne, g);
            const V top = hn::Add(sizes[b], one);
            g = hn::Floor(hn::IfThenElse(hn::Lt(top, g), top, g));
            g = hn::IfThenElse(up[b], hn::Min(hn::Max(g, firstCell), last),
                               hn::Max(hn::Min(g, firstCell), last));
            for (;;) {
                const M back = hn::And(
                    need, hn::AndNot(taken(exitAt(b, hn::Sub(g, stp[b]))), hn::Ne(g, firstCell)));
                if (hn::AllFalse(d, back)) break;
                g = hn::IfThenElse(back, hn::Sub(g, stp[b]), g);
            }
            V tc = exitAt(b, g);
            for (;;) {
                const M forward = hn::And(need, hn::And(hn::Ne(g, last), taken(tc)));
                if (hn::AllFalse(d, forward)) break;
                g = hn::IfThenElse(forward, hn::Add(g, stp[b]), g);
                tc = hn::IfThenElse(forward, exitAt(b, g), tc);
            }
            cell[b] = hn::IfThenElse(need, g, cell[b]);
            next[b] = hn::IfThenElse(need, tc, next[b]);
        }
        // The exit axis crosses its box plane.
        M left = hn::Gt(tJump, vtMax);
        V jumpCell[3], jumpNext[3];
        for (int a = 0; a < 3; ++a) {
            jumpCell[a] = hn::IfThenElse(up[a], hn::Add(hi[a], one), hn::Sub(lo[a], one));
            left = hn::Or(left, hn::And(sel[a], hn::Or(hn::Lt(jumpCell[a], zero),
                                                       hn::Ge(jumpCell[a], sizes[a]))));
            jumpNext[a] = exitAt(a, jumpCell[a]);
        }
        const V jumpAxis =
            hn::IfThenElse(sel[0], zero, hn::IfThenElse(sel[1], one, hn::Set(d, 2.0)));

        HWY_ALIGN double outCell[3][kMaxLanes], outNext[3][kMaxLanes], outInv[3][kMaxLanes];
        HWY_ALIGN double outT[kMaxLanes], outAxis[kMaxLanes], outKind[kMaxLanes];
        const M jumped = hn::AndNot(left, settleLanes);
        for (int a = 0; a < 3; ++a) {
            const M mine = hn::And(jumped, sel[a]);
            hn::Store(hn::IfThenElse(mine, jumpCell[a], cell[a]), d, outCell[a]);
            hn::Store(hn::IfThenElse(mine, jumpNext[a], next[a]), d, outNext[a]);
            hn::Store(inv[a], d, outInv[a]);
        }
        hn::Store(hn::IfThenElse(jumped, tJump, t0), d, outT);
        hn::Store(hn::IfThenElse(jumped, jumpAxis, enterAxis), d, outAxis);
        // The kind, in the order of precedence: one-ray, start missed, not taken, jump missed,
        // jumped.
        V kind = hn::Set(d, double(PlaneStart::Jumped));
        kind = hn::IfThenElse(left, hn::Set(d, double(PlaneStart::JumpMissed)), kind);
        kind = hn::IfThenElse(notTaken, hn::Set(d, double(PlaneStart::NotTaken)), kind);
        kind = hn::IfThenElse(missed, hn::Set(d, double(PlaneStart::StartMissed)), kind);
        kind = hn::IfThenElse(oneRay, hn::Set(d, double(PlaneStart::OneRay)), kind);
        hn::Store(kind, d, outKind);
        for (std::size_t l = 0; l < n; ++l) {
            const Ray& r = rays[first + l];
            const PlaneStart s = static_cast<PlaneStart>(static_cast<int>(outKind[l]));
            starts[first + l] = s;
            if (s != PlaneStart::Jumped && s != PlaneStart::NotTaken) continue;
            shared::VoxelWalk& w = walks[first + l];
            w.o = toShared(r.origin);
            w.d = toShared(r.direction);
            w.inv = shared::dvec3(outInv[0][l], outInv[1][l], outInv[2][l]);
            w.size = shared::ivec3(size.x, size.y, size.z);
            for (int a = 0; a < 3; ++a) {
                w.stp[a] = r.direction[a] > 0.0 ? 1 : -1;
                w.cell[a] = static_cast<int>(outCell[a][l]);
                w.next[a] = outNext[a][l];
            }
            w.t = outT[l];
            w.axis = static_cast<int>(outAxis[l]);
        }
    }
}

}  // namespace luxel::voxel::stream::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace luxel::voxel::stream {

HWY_EXPORT(StartAtPlane);

void startAtPlane(const VoxelWorld& world, std::span<const Ray> rays, Skip skip, double tMax,
                  gpu::shared::VoxelWalk* walks, PlaneStart* starts) {
    HWY_DYNAMIC_DISPATCH(StartAtPlane)(world, rays.data(), rays.size(), skip, tMax, walks, starts);
}

}  // namespace luxel::voxel::stream
#endif
