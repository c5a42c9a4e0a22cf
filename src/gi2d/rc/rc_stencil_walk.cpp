// The SIMD stencil walk of the CPU RC pass (docs/algorithms/radiance-cascades-2d.md §8): one lane
// per probe, all lanes stepping through the same stencil entry at once, each adding its cell's
// optical depth; then the merge with what lies beyond. Compiled for every instruction set Highway
// targets; the best one runs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gi2d/rc/rc_stencil_walk.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// foreach_target.h first: it includes this file once per target.
#include <hwy/cache_control.h>
#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "gi2d/rc/rc_stencil.h"

HWY_BEFORE_NAMESPACE();
namespace luxel::gi2d::rc {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::CappedTag<float, kStencilLanes>;
using DI = hn::RebindToSigned<D>;
using VF = hn::Vec<D>;
using VI = hn::Vec<DI>;
using MF = hn::Mask<D>;
using MI = hn::Mask<DI>;

// -ln(1e-6): RayMarcher stops a ray once every channel's transmittance is below 1e-6.
constexpr float kCutoffDepth = 13.815510557964274f;
// A walk crosses a uniform square in one step where every lane's is at least this wide (in
// radius) and the step spans at least kMinSkip entries; below, entry by entry is faster.
constexpr int kSkipRadius = 2;
constexpr int kMinSkip = 4;
// Walks of fewer entries never try.
constexpr int kCrossingWalk = 12;

int LanesImpl() {
    return static_cast<int>(hn::Lanes(D()));
}

// Light and transmittance of one walk.
struct Segment {
    VF light[3];
    VF transmittance[3];
};

// The emitting cell a lane entered last and its optical depth before that cell. A lane adds
// T E (1 - t) there (T = exp(-tau) before the cell, t = exp(-sigma l) across it), as RayMarcher
// does per run, once the walk is over or the lane enters the next emitting cell: most lanes meet
// one emitter (an opaque wall) and stop, so the gathers and exponentials run once per walk.
template <bool kGrey>
struct Pending {
    VI pixel;  // y * width + x
    VF length;
    VF tau[kGrey ? 1 : 3];
    MF any;
};

template <bool kGrey>
HWY_NOINLINE void AddEmission(const StencilGroup& g, const Pending<kGrey>& pending, MF lanes,
                              VF (&light)[3]) {
    const D df;
    const DI di;
    const StencilMedium& m = *g.medium;
    VF minTau = pending.tau[0];
    for (int c = 1; c < (kGrey ? 1 : 3); ++c) minTau = hn::Min(minTau, pending.tau[c]);
    lanes = hn::And(lanes, hn::Le(minTau, hn::Set(df, kCutoffDepth)));
    const VI pixel = hn::IfThenElseZero(hn::RebindMask(di, lanes), pending.pixel);
    const VI id = hn::GatherIndex(di, reinterpret_cast<const std::int32_t*>(m.ids()), pixel);
    const VF length = pending.length;
    VF before, across;
    for (int c = 0; c < 3; ++c) {
        if (!kGrey || c == 0) {
            const VF sigma = hn::GatherIndex(df, m.sigma(c), id);
            before = hn::Exp(df, hn::Neg(pending.tau[kGrey ? 0 : c]));
            across = hn::Neg(hn::Expm1(df, hn::Neg(hn::Mul(sigma, length))));
        }
        const VF emission = hn::GatherIndex(df, m.emission(c), id);
        light[c] = hn::IfThenElse(lanes, hn::MulAdd(hn::Mul(before, emission), across, light[c]),
                                  light[c]);
    }
}

// One walk, advanced an iteration at a time: a group's walks (and several groups') take turns,
// so that the memory reads of one overlap the others' (a step across a square lands far away).
template <bool kGrey>
class Walker {
  public:
    static constexpr int kChannels = kGrey ? 1 : 3;

    HWY_INLINE void init(const StencilGroup& g, const StencilGroup::Walk& w) {
        g_ = &g, w_ = &w;
        // Optical depth in two sums, of the even and the odd entries, so that consecutive cells
        // do not wait on each other. Lanes past `lanes` start beyond the cutoff, never counting.
        const VF start = hn::IfThenElse(hn::FirstN(df, static_cast<std::size_t>(g.lanes)),
                                        hn::Zero(df), hn::Set(df, HUGE_VALF));
        for (int c = 0; c < kChannels; ++c) even_[c] = start, odd_[c] = hn::Zero(df);
        for (VF& l : out_.light) l = hn::Zero(df);
        pending_.pixel = hn::Zero(di);
        pending_.length = hn::Zero(df);
        for (VF& t : pending_.tau) t = hn::Zero(df);
        pending_.any = hn::FirstN(df, 0);
        // Lane l's pixel at entry j: laneX + cellX[j] + cellY[j] * width.
        width_ = g.medium->width();
        laneX_ = hn::Add(hn::Mul(hn::Iota(di, 0), hn::Set(di, g.laneStride)),
                         hn::Set(di, w.shiftX + w.shiftY * width_));
        done_ = hn::Gt(start, hn::Set(df, kCutoffDepth));  // lanes past the cutoff
        // Relative to the first cell, lane l's cells lie on the canvas in columns ra..rb,
        // which holds for entries onFrom <= j < onTo (firstX), the walk's rows being on the
        // canvas; it reads vacuum outside. Short walks (the lower cascades) step entry by
        // entry: their lanes count to the end.
        crossSquares_ = w.end - w.begin >= kCrossingWalk;
        onFrom_ = hn::Set(di, w.begin), onTo_ = hn::Set(di, w.end);
        if (crossSquares_) {
            onTo_ = onFrom_;
            const VI x = hn::Add(hn::Mul(hn::Iota(di, 0), hn::Set(di, g.laneStride)),
                                 hn::Set(di, w.shiftX + w.cellX0));
            const VI lo = hn::Neg(x), hi = hn::Sub(hn::Set(di, width_ - 1), x);
            const bool up = w.signX > 0;
            const VI ra = hn::Max(up ? lo : hn::Neg(hi), hn::Zero(di));
            const VI rb = hn::Min(up ? hi : hn::Neg(lo), hn::Set(di, w.spanX));
            const MI some = hn::And(hn::Not(hn::Lt(rb, ra)), hn::FirstN(di, g.lanes));
            const VI ea =
                hn::Max(hn::GatherIndex(di, w.firstX, hn::IfThenElseZero(some, ra)), onFrom_);
            const VI eb =
                hn::Min(hn::GatherIndex(di, w.firstX,
                                        hn::IfThenElseZero(some, hn::Add(rb, hn::Set(di, 1)))),
                        hn::Set(di, w.end));
            const MI on = hn::And(some, hn::Lt(ea, eb));
            onFrom_ = hn::IfThenElse(on, ea, onFrom_);
            onTo_ = hn::IfThenElse(on, eb, onTo_);
        }
        j_ = w.begin;
        finished_ = j_ >= w.end;
    }

    bool finished() const { return finished_; }

    // One step across a uniform square, or two entries.
    HWY_INLINE void advance() {
        const StencilGroup::Walk& w = *w_;
        int j = j_;
        const int next = crossSquares_ && w.end - j >= kMinSkip ? skip(j) : j;
        if (next == j) {
            if (j + 1 < w.end) {
                step(j, even_);
                step(j + 1, odd_);
                j += 2;
            } else {
                step(j, even_);
                j += 1;
            }
        } else {
            j = next;
        }
        j_ = j;
        done_ = hn::Gt(minDepth(), hn::Set(df, kCutoffDepth));
        const MF left = hn::RebindMask(df, hn::Not(hn::Lt(hn::Set(di, j), onTo_)));
        finished_ = j >= w.end || hn::AllTrue(df, hn::Or(done_, left));
    }

    Segment result() {
        if (!hn::AllFalse(df, pending_.any)) {
            AddEmission<kGrey>(*g_, pending_, pending_.any, out_.light);
        }
        for (int c = 0; c < 3; ++c) {
            out_.transmittance[c] = (kGrey && c > 0) ? out_.transmittance[0]
                                                     : hn::Exp(df, hn::Neg(depth(kGrey ? 0 : c)));
        }
        return out_;
    }

  private:
    VF depth(int c) const { return hn::Add(even_[c], odd_[c]); }
    VF minDepth() const {
        VF m = depth(0);
        for (int c = 1; c < kChannels; ++c) m = hn::Min(m, depth(c));
        return m;
    }

    // Lanes `emits` enter an emitting cell at entry j (optical depth before it `before`).
    void enter(MF emits, int j, const VF (&before)[kChannels], VF length) {
        const MF again = hn::And(emits, pending_.any);
        if (HWY_UNLIKELY(!hn::AllFalse(df, again))) {
            AddEmission<kGrey>(*g_, pending_, again, out_.light);
        }
        const VI pixel = hn::Add(laneX_, hn::Set(di, w_->cellX[j] + w_->cellY[j] * width_));
        pending_.pixel = hn::IfThenElse(hn::RebindMask(di, emits), pixel, pending_.pixel);
        pending_.length = hn::IfThenElse(emits, length, pending_.length);
        for (int c = 0; c < kChannels; ++c) {
            pending_.tau[c] = hn::IfThenElse(emits, before[c], pending_.tau[c]);
        }
        pending_.any = hn::Or(pending_.any, emits);
    }

    // One entry into the sums `tau`; the sign bit of the first plane marks an emitting cell.
    void step(int j, VF (&tau)[kChannels]) {
        const StencilGroup& g = *g_;
        const std::int64_t base = w_->base;
        const std::int64_t o = base + w_->offset[j];
        const std::int64_t ahead = base + w_->offset[j + kStencilPrefetch];
        hwy::Prefetch(g.planes[0] + ahead);
        hwy::Prefetch(g.radius + ahead);
        const VF s0 = hn::LoadU(df, g.planes[0] + o);
        const VF length = hn::Set(df, w_->length[j]);
        const MF emits =
            hn::AndNot(done_, hn::RebindMask(df, hn::Lt(hn::BitCast(di, s0), hn::Zero(di))));
        if (HWY_UNLIKELY(!hn::AllFalse(df, emits))) {
            // `done` is the pair's: leave out the lanes the entry before stopped.
            VF before[kChannels];
            for (int c = 0; c < kChannels; ++c) before[c] = depth(c);
            const MF live = hn::AndNot(hn::Gt(minDepth(), hn::Set(df, kCutoffDepth)), emits);
            if (!hn::AllFalse(df, live)) enter(live, j, before, length);
        }
        tau[0] = hn::MulAdd(hn::Abs(s0), length, tau[0]);
        for (int c = 1; c < kChannels; ++c) {
            tau[c] = hn::MulAdd(hn::LoadU(df, g.planes[c] + o), length, tau[c]);
        }
    }

    // Crosses entries j.. in one step where every lane that counts lies in a uniform square of
    // radius kSkipRadius or more (StencilMedium::uniformRadius) that does not emit: the
    // entries within the smallest such radius of entry j's cell (in both axes, the stencil
    // being monotone) add sigma times their length. Returns the entry after them, or j.
    int skip(int j) {
        const StencilGroup& g = *g_;
        const StencilGroup::Walk& w = *w_;
        const hn::Rebind<std::uint8_t, DI> d8;
        const VI noLimit = hn::Set(di, std::numeric_limits<std::int32_t>::max());
        const VI at = hn::Set(di, j);
        const MF ahead = hn::RebindMask(df, hn::Lt(at, onFrom_));
        const MF live = hn::AndNot(hn::Or(done_, ahead), hn::RebindMask(df, hn::Lt(at, onTo_)));
        const std::int64_t o = w.base + w.offset[j];
        const VI radius = hn::PromoteTo(di, hn::LoadU(d8, g.radius + o));
        const MF narrow = hn::RebindMask(df, hn::Lt(radius, hn::Set(di, kSkipRadius)));
        if (!hn::AllFalse(df, hn::And(live, narrow))) return j;
        // Lanes still off the canvas stop the step where they enter it.
        int e = w.end;
        const MF waiting = hn::AndNot(done_, ahead);
        if (!hn::AllFalse(df, waiting)) {
            e = std::min(e,
                         hn::GetLane(hn::MinOfLanes(
                             di, hn::IfThenElse(hn::RebindMask(di, waiting), onFrom_, noLimit))));
        }
        int r = StencilMedium::kMaxUniformRadius;
        if (!hn::AllFalse(df, live)) {
            r = hn::GetLane(
                hn::MinOfLanes(di, hn::IfThenElse(hn::RebindMask(di, live), radius, noLimit)));
        }
        const int rx = std::min((w.cellX[j] - w.cellX0) * w.signX + r + 1, w.spanX + 1);
        const int ry = std::min((w.cellY[j] - w.cellY0) * w.signY + r + 1, w.spanY + 1);
        e = std::min({e, w.firstX[rx], w.firstY[ry]});
        if (e - j < kMinSkip) return j;
        const VF s0 = hn::LoadU(df, g.planes[0] + o);
        const MF emits = hn::RebindMask(df, hn::Lt(hn::BitCast(di, s0), hn::Zero(di)));
        if (!hn::AllFalse(df, hn::And(live, emits))) return j;
        const VF length = hn::Set(df, static_cast<float>(w.cum[e] - w.cum[j]));
        even_[0] = hn::MulAdd(hn::Abs(s0), length, even_[0]);
        for (int c = 1; c < kChannels; ++c) {
            even_[c] = hn::MulAdd(hn::LoadU(df, g.planes[c] + o), length, even_[c]);
        }
        return e;
    }

    static constexpr D df{};
    static constexpr DI di{};
    const StencilGroup* g_;
    const StencilGroup::Walk* w_;
    VF even_[kChannels], odd_[kChannels];
    Segment out_;
    Pending<kGrey> pending_;
    int width_;
    VI laneX_;
    MF done_;
    bool crossSquares_, finished_;
    VI onFrom_, onTo_;
    int j_;
};

// sum += the merge of the group's walks with what lies beyond them.
void Merge(const StencilGroup& g, const Segment (&walks)[4]) {
    const D df;
    const DI di;
    const MF lanes = hn::FirstN(df, static_cast<std::size_t>(g.lanes));
    VF sum[3];
    for (int ch = 0; ch < 3; ++ch) sum[ch] = hn::LoadU(df, g.sum[ch]);
    for (int c = 0; c < g.corners; ++c) {
        Segment s = walks[c];
        MF use = lanes;
        if (g.source != nullptr) {  // lanes whose corner another walk serves, or none
            const VI source = hn::LoadU(di, g.source + c * kStencilLanes);
            use = hn::And(use, hn::RebindMask(df, hn::Gt(source, hn::Set(di, -1))));
            for (int other = 0; other < g.corners; ++other) {
                if (other == c) continue;
                const MF from = hn::RebindMask(df, hn::Eq(source, hn::Set(di, other)));
                for (int ch = 0; ch < 3; ++ch) {
                    s.light[ch] = hn::IfThenElse(from, walks[other].light[ch], s.light[ch]);
                    s.transmittance[ch] =
                        hn::IfThenElse(from, walks[other].transmittance[ch], s.transmittance[ch]);
                }
            }
        }
        const VF weight = hn::Set(df, g.weight[c]);
        for (int ch = 0; ch < 3; ++ch) {
            const VF beyond = hn::LoadU(df, g.beyond[c][ch]);
            const VF merged = hn::MulAdd(s.transmittance[ch], beyond, s.light[ch]);
            sum[ch] = hn::IfThenElse(use, hn::MulAdd(merged, weight, sum[ch]), sum[ch]);
        }
    }
    for (int ch = 0; ch < 3; ++ch) hn::StoreU(sum[ch], df, g.sum[ch]);
}

template <bool kGrey>
void Groups(const StencilGroup* groups, int count) {
    // Short walks run one after the other (their state stays in registers); long ones, whose
    // steps across squares read far apart, take turns.
    Segment results[kStencilBatchWalks];
    Walker<kGrey> walkers[kStencilBatchWalks];
    int slot[kStencilBatchWalks];
    int n = 0, i = 0;
    for (int b = 0; b < count; ++b) {
        for (int c = 0; c < groups[b].corners; ++c, ++i) {
            const StencilGroup::Walk& w = groups[b].walk[c];
            if (w.end - w.begin >= kCrossingWalk) {
                walkers[n].init(groups[b], w);
                slot[n++] = i;
                continue;
            }
            Walker<kGrey> walker;
            walker.init(groups[b], w);
            while (!walker.finished()) walker.advance();
            results[i] = walker.result();
        }
    }
    for (bool any = n > 0; any;) {
        any = false;
        for (int k = 0; k < n; ++k) {
            if (walkers[k].finished()) continue;
            walkers[k].advance();
            any = true;
        }
    }
    for (int k = 0; k < n; ++k) results[slot[k]] = walkers[k].result();
    for (int b = 0, r = 0; b < count; ++b) {
        Segment walks[4];
        for (int c = 0; c < groups[b].corners; ++c) walks[c] = results[r++];
        Merge(groups[b], walks);
    }
}

void GroupsImpl(const StencilGroup* groups, int count) {
    if (groups[0].grey) {
        Groups<true>(groups, count);
    } else {
        Groups<false>(groups, count);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace luxel::gi2d::rc
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace luxel::gi2d::rc {

HWY_EXPORT(LanesImpl);
HWY_EXPORT(GroupsImpl);

int stencilWalkLanes() {
    return HWY_DYNAMIC_DISPATCH(LanesImpl)();
}

void walkStencilGroups(const StencilGroup* groups, int count) {
    HWY_DYNAMIC_DISPATCH(GroupsImpl)(groups, count);
}

}  // namespace luxel::gi2d::rc
#endif
