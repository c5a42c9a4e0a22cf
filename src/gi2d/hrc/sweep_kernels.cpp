// Highway implementations of the streaming HRC row loops, compiled once per SIMD target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gi2d/hrc/sweep_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// foreach_target.h re-includes this file per target; highway.h must follow it.
#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

#if HWY_ARCH_X86
#include <xmmintrin.h>
#endif

#include "gi2d/hrc/sweep_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace luxel::gi2d::hrc {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DH = hn::Rebind<hwy::float16_t, DF>;
using VF = hn::Vec<DF>;

// An interval per lane: L and T per channel.
struct Lanes6 {
    VF l[3], t[3];
};

HWY_INLINE VF LoadHalf(const std::uint16_t* p, int y) {
    const DF df;
    const DH dh;
    return hn::PromoteTo(df, hn::LoadU(dh, reinterpret_cast<const hwy::float16_t*>(p + y)));
}

// kPresent: the caller knows `plane[0]` is set, so no test per vector.
template <bool kPresent = false>
HWY_INLINE Lanes6 LoadInterval(const IntervalRows& rows, int y) {
    const DF df;
    Lanes6 v;
    for (int c = 0; c < 3; ++c) {
        if (!kPresent && rows.plane[0] == nullptr) {
            v.l[c] = hn::Zero(df);
            v.t[c] = hn::Set(df, 1.0f);
        } else {
            v.l[c] = LoadHalf(rows.plane[c], y + rows.offset);
            v.t[c] = LoadHalf(rows.plane[3 + c], y + rows.offset);
        }
    }
    return v;
}

// Front-to-back compositing, paper Eq 8 (hrcOver).
HWY_INLINE Lanes6 Over(const Lanes6& near, const Lanes6& far) {
    Lanes6 v;
    for (int c = 0; c < 3; ++c) {
        v.l[c] = hn::Add(near.l[c], hn::Mul(near.t[c], far.l[c]));
        v.t[c] = hn::Mul(near.t[c], far.t[c]);
    }
    return v;
}

// Subnormal floats read and made as zero (x86 MXCSR DAZ and FTZ) while it lives, on this thread.
// Behind two opaque cells (sigma 50: t about e^-50) a traced ray's T falls below the smallest
// normal float, and each subnormal product took a microcode assist of some hundred cycles: a
// quarter of the trace's time on the room at 1024^2 (docs/performance.md, HRC). The stored
// binary16 intervals keep their bits: any T below 2^-126 rounds to binary16 0 either way, and
// once T is that small every later term T l of L is below half an ulp of any L binary16 does not
// round to 0 (SweepKernels.TraceBehindOpaqueCellsStoresWhatUnflushedFloatsGive).
class FlushSubnormals {
  public:
#if HWY_ARCH_X86
    FlushSubnormals() : saved_(_mm_getcsr()) {
        _mm_setcsr(saved_ | 0x8040u);
    }
    ~FlushSubnormals() {
        _mm_setcsr(saved_);
    }

  private:
    unsigned saved_;
#endif
};

// Stores the first `count` lanes (all of them for whole vectors).
HWY_INLINE void StoreHalves(VF v, std::uint16_t* p, int y, int count) {
    const DF df;
    const DH dh;
    const auto h = hn::DemoteTo(dh, v);
    if (count == static_cast<int>(hn::Lanes(df))) {
        hn::StoreU(h, dh, reinterpret_cast<hwy::float16_t*>(p + y));
        return;
    }
    HWY_ALIGN hwy::float16_t tmp[hn::MaxLanes(dh)];
    hn::Store(h, dh, tmp);
    std::memcpy(p + y, tmp, static_cast<std::size_t>(count) * sizeof(std::uint16_t));
}

HWY_INLINE void StoreFloats(VF v, float* p, int y, int count) {
    const DF df;
    if (count == static_cast<int>(hn::Lanes(df))) {
        hn::StoreU(v, df, p + y);
        return;
    }
    HWY_ALIGN float tmp[hn::MaxLanes(df)];
    hn::Store(v, df, tmp);
    std::memcpy(p + y, tmp, static_cast<std::size_t>(count) * sizeof(float));
}

HWY_INLINE void StoreInterval(const IntervalRowsOut& out, int y, const Lanes6& v, int count) {
    for (int c = 0; c < 3; ++c) {
        StoreHalves(v.l[c], out.plane[c], y, count);
        StoreHalves(v.t[c], out.plane[3 + c], y, count);
    }
}

void TraceRowsImpl(const TraceStep* steps, std::size_t stepCount, const CellTransfer* columns,
                   IntervalRowsOut out, int y0, int y1) {
    const FlushSubnormals flush;
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    for (int y = y0; y < y1; y += lanes) {
        Lanes6 acc;
        for (int c = 0; c < 3; ++c) acc.l[c] = hn::Zero(df), acc.t[c] = hn::Set(df, 1.0f);
        for (std::size_t s = 0; s < stepCount; ++s) {
            const CellTransfer& cell = columns[steps[s].column];
            const int row = y + steps[s].dv;
            for (int c = 0; c < 3; ++c) {
                const VF t = hn::LoadU(df, cell.plane[c] + row);
                const VF l = hn::LoadU(df, cell.plane[3 + c] + row);
                acc.l[c] = hn::Add(acc.l[c], hn::Mul(acc.t[c], l));
                acc.t[c] = hn::Mul(acc.t[c], t);
            }
        }
        StoreInterval(out, y, acc, std::min(lanes, y1 - y));
    }
}

void CellTransferRowsImpl(const float* const sigma[3], const float* const emission[3], float length,
                          float* const t[3], float* const l[3], int count) {
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), negLength = hn::Set(df, -length);
    for (int v = 0; v < count; v += lanes) {
        const int n = std::min(lanes, count - v);
        VF s[3], tc[3];
        for (int c = 0; c < 3; ++c) s[c] = hn::LoadU(df, sigma[c] + v);
        // Grey absorption, the common case, needs one exp for the three channels.
        const bool grey = hn::AllTrue(df, hn::And(hn::Eq(s[0], s[1]), hn::Eq(s[1], s[2])));
        for (int c = 0; c < 3; ++c) {
            tc[c] = grey && c > 0 ? tc[0]
                                  : hn::IfThenElse(hn::Eq(s[c], zero), one,
                                                   hn::Exp(df, hn::Mul(s[c], negLength)));
            const VF lc = hn::Mul(hn::LoadU(df, emission[c] + v), hn::Sub(one, tc[c]));
            StoreFloats(tc[c], t[c], v, n);
            StoreFloats(lc, l[c], v, n);
        }
    }
}

void AddRgbPlanesImpl(float* to, const float* const fromRef[3], int count) {
    const float* const from[3] = {fromRef[0], fromRef[1], fromRef[2]};
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    int i = 0;
    for (; i + lanes <= count; i += lanes) {
        float* const at = to + 3 * static_cast<std::ptrdiff_t>(i);
        VF r, g, b;
        hn::LoadInterleaved3(df, at, r, g, b);
        r = hn::Add(r, hn::LoadU(df, from[0] + i));
        g = hn::Add(g, hn::LoadU(df, from[1] + i));
        b = hn::Add(b, hn::LoadU(df, from[2] + i));
        hn::StoreInterleaved3(r, g, b, df, at);
    }
    for (; i < count; ++i) {
        for (int c = 0; c < 3; ++c) to[3 * static_cast<std::ptrdiff_t>(i) + c] += from[c][i];
    }
}

void AddGatheredRowsImpl(float* to, std::ptrdiff_t toStride, const float* from, int fromStride,
                         const std::int32_t* index, int floats, int rows, int prefetchRows) {
    const DF df;
    const hn::RebindToSigned<DF> di;
    const int lanes = static_cast<int>(hn::Lanes(df));
    for (int r = 0; r < rows; ++r) {
        float* const row = to + r * toStride;
        const float* const base = from + static_cast<std::ptrdiff_t>(r) * fromStride;
        if (r + prefetchRows < rows) {
            const float* ahead = row + prefetchRows * toStride;
            for (int k = 0; k < floats + 16; k += 16) __builtin_prefetch(ahead + k, 1);
        }
        int k = 0;
        for (; k + lanes <= floats; k += lanes) {
            const VF add = hn::GatherIndex(df, base, hn::LoadU(di, index + k));
            hn::StoreU(hn::Add(hn::LoadU(df, row + k), add), df, row + k);
        }
        for (; k < floats; ++k) row[k] += base[index[k]];
    }
}

void ExtendRowsImpl(const IntervalRows& nearARef, const IntervalRows& farARef,
                    const IntervalRows& nearBRef, const IntervalRows& farBRef, bool twoPaths,
                    IntervalRowsOut out, int y0, int y1) {
    // Local copies: stores through `out` cannot alias them, so their pointers stay in registers.
    const IntervalRows nearA = nearARef, farA = farARef, nearB = nearBRef, farB = farBRef;
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const VF half = hn::Set(df, 0.5f);
    for (int y = y0; y < y1; y += lanes) {
        Lanes6 v = Over(LoadInterval(nearA, y), LoadInterval(farA, y));
        if (twoPaths) {
            const Lanes6 b = Over(LoadInterval(nearB, y), LoadInterval(farB, y));
            for (int c = 0; c < 3; ++c) {
                v.l[c] = hn::Mul(hn::Add(v.l[c], b.l[c]), half);
                v.t[c] = hn::Mul(hn::Add(v.t[c], b.t[c]), half);
            }
        }
        StoreInterval(out, y, v, std::min(lanes, y1 - y));
    }
}

template <bool kPresent = false>
HWY_INLINE VF LoadCone(const ConeRows& rows, int c, int y) {
    const DF df;
    if (!kPresent && rows.plane[0] == nullptr) return hn::Set(df, rows.fill[c]);
    return LoadHalf(rows.plane[c], y + rows.offset);
}

// (1 - s) a + s b, or a alone when s = 0 (hrcBlendTwoRows, §5.1).
template <bool kPresent = false>
HWY_INLINE VF TwoRows(const ConeRows& a, const ConeRows& b, int c, int y, float second) {
    const DF df;
    if (second == 0.0f) return LoadCone<kPresent>(a, c, y);
    return hn::Add(hn::Mul(LoadCone<kPresent>(a, c, y), hn::Set(df, 1.0f - second)),
                   hn::Mul(LoadCone<kPresent>(b, c, y), hn::Set(df, second)));
}

// The same with a weight per lane (the near probe next to a light, hrcNearRowWeightAt).
template <bool kPresent = false>
HWY_INLINE VF TwoRowsPerLane(const ConeRows& a, const ConeRows& b, int c, int y, VF second) {
    const DF df;
    return hn::Add(hn::Mul(LoadCone<kPresent>(a, c, y), hn::Sub(hn::Set(df, 1.0f), second)),
                   hn::Mul(LoadCone<kPresent>(b, c, y), second));
}

// (1 - 3s/2) a + s b + (s/2) d (hrcBlendThreeRows, §5.1).
template <bool kPresent = false>
HWY_INLINE VF ThreeRows(const ConeRows& a, const ConeRows& b, const ConeRows& d, int c, int y,
                        float second) {
    const DF df;
    const VF ab = hn::Add(hn::Mul(LoadCone<kPresent>(a, c, y), hn::Set(df, 1.0f - 1.5f * second)),
                          hn::Mul(LoadCone<kPresent>(b, c, y), hn::Set(df, second)));
    return hn::Add(ab, hn::Mul(LoadCone<kPresent>(d, c, y), hn::Set(df, 0.5f * second)));
}

// The near probe's read on even planes (§5.1): its row alone, blended with the row along the
// side's ray by a constant weight, or by a weight per row (next to a light).
enum class NearRead { kOneRow, kTwoRows, kPerRow };

// One side's share of a cone at rows y .. y + lanes - 1, added to sum (Eq 14 or Eq 15-17).
template <bool kOdd, NearRead kNear, bool kPresent>
HWY_INLINE void MergeSideRows(const MergeSide& side, int y, float second, float nearSecond,
                              VF nearHere, VF sum[3]) {
    const DF df;
    const VF w = hn::Set(df, side.weight);
    const Lanes6 here = LoadInterval<true>(side.here, y);
    if (kOdd) {  // Eq 14 (hrcMergeOdd)
        for (int c = 0; c < 3; ++c) {
            const VF upper = TwoRows<kPresent>(side.upperA, side.upperA2, c, y, second);
            sum[c] = hn::Add(sum[c], hn::Add(hn::Mul(here.l[c], w), hn::Mul(here.t[c], upper)));
        }
        return;
    }
    // Eq 15-17 (hrcMergeEven): the double-length ray to the far probe.
    const VF half = hn::Set(df, 0.5f);
    const Lanes6 ray = Over(here, LoadInterval<kPresent>(side.next, y));
    for (int c = 0; c < 3; ++c) {
        const VF upperFar =
            ThreeRows<kPresent>(side.upperB, side.upperB2, side.upperB3, c, y, second);
        const VF far = hn::Add(hn::Mul(ray.l[c], w), hn::Mul(ray.t[c], upperFar));
        VF upperNear;
        if (kNear == NearRead::kPerRow) {
            upperNear = TwoRowsPerLane<kPresent>(side.upperA, side.upperA2, c, y, nearHere);
        } else if (kNear == NearRead::kTwoRows) {
            upperNear = TwoRows<kPresent>(side.upperA, side.upperA2, c, y, nearSecond);
        } else {
            upperNear = LoadCone<kPresent>(side.upperA, c, y);
        }
        sum[c] = hn::Add(sum[c], hn::Mul(hn::Add(upperNear, far), half));
    }
}

template <bool kOdd, NearRead kNear, bool kPresent>
HWY_NOINLINE void MergeLoop(const MergeSide& side0, const MergeSide& side1, float second,
                            float nearSecond, const float* nearRows, std::uint16_t* const out[3],
                            int y0, int y1) {
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    for (int y = y0; y < y1; y += lanes) {
        VF sum[3] = {hn::Zero(df), hn::Zero(df), hn::Zero(df)};
        const VF nearHere = kNear == NearRead::kPerRow ? hn::LoadU(df, nearRows + y) : hn::Zero(df);
        MergeSideRows<kOdd, kNear, kPresent>(side0, y, second, nearSecond, nearHere, sum);
        MergeSideRows<kOdd, kNear, kPresent>(side1, y, second, nearSecond, nearHere, sum);
        const int count = std::min(lanes, y1 - y);
        for (int c = 0; c < 3; ++c) StoreHalves(sum[c], out[c], y, count);
    }
}

// Runs MergeLoop for the case: kPresent where every source the loop reads is inside the frame
// (most rows), which spares a test per source and vector.
template <bool kOdd, NearRead kNear>
HWY_INLINE void MergeCase(const MergeSide& side0, const MergeSide& side1, float second,
                          float nearSecond, const float* nearRows, std::uint16_t* const out[3],
                          int y0, int y1) {
    bool present = true;
    for (const MergeSide* side : {&side0, &side1}) {
        present = present && side->here.plane[0] != nullptr && side->upperA.plane[0] != nullptr;
        if (kOdd || kNear != NearRead::kOneRow) {
            present = present && side->upperA2.plane[0] != nullptr;
        }
        if (!kOdd) {
            present = present && side->next.plane[0] != nullptr &&
                      side->upperB.plane[0] != nullptr && side->upperB2.plane[0] != nullptr &&
                      side->upperB3.plane[0] != nullptr;
        }
    }
    if (present) {
        MergeLoop<kOdd, kNear, true>(side0, side1, second, nearSecond, nearRows, out, y0, y1);
    } else {
        MergeLoop<kOdd, kNear, false>(side0, side1, second, nearSecond, nearRows, out, y0, y1);
    }
}

void MergeRowsImpl(bool odd, const MergeSide& side0, const MergeSide& side1, float second,
                   float nearSecond, const float* nearRows, std::uint16_t* const outRef[3], int y0,
                   int y1) {
    std::uint16_t* const out[3] = {outRef[0], outRef[1], outRef[2]};
    // One loop per case, so each holds only its own reads.
    if (odd) {
        MergeCase<true, NearRead::kOneRow>(side0, side1, second, 0.0f, nullptr, out, y0, y1);
    } else if (nearRows != nullptr) {
        MergeCase<false, NearRead::kPerRow>(side0, side1, second, 0.0f, nearRows, out, y0, y1);
    } else if (nearSecond != 0.0f) {
        MergeCase<false, NearRead::kTwoRows>(side0, side1, second, nearSecond, nullptr, out, y0,
                                             y1);
    } else {
        MergeCase<false, NearRead::kOneRow>(side0, side1, second, 0.0f, nullptr, out, y0, y1);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace luxel::gi2d::hrc
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace luxel::gi2d::hrc {

HWY_EXPORT(TraceRowsImpl);
HWY_EXPORT(CellTransferRowsImpl);
HWY_EXPORT(AddRgbPlanesImpl);
HWY_EXPORT(AddGatheredRowsImpl);
HWY_EXPORT(ExtendRowsImpl);
HWY_EXPORT(MergeRowsImpl);

void traceRows(std::span<const TraceStep> steps, const CellTransfer* columns, IntervalRowsOut out,
               int y0, int y1) {
    HWY_DYNAMIC_DISPATCH(TraceRowsImpl)(steps.data(), steps.size(), columns, out, y0, y1);
}

void cellTransferRows(const float* const sigma[3], const float* const emission[3], float length,
                      float* const t[3], float* const l[3], int count) {
    HWY_DYNAMIC_DISPATCH(CellTransferRowsImpl)(sigma, emission, length, t, l, count);
}

void addRgbPlanes(float* to, const float* const from[3], int count) {
    HWY_DYNAMIC_DISPATCH(AddRgbPlanesImpl)(to, from, count);
}

void addGatheredRows(float* to, std::ptrdiff_t toStride, const float* from, int fromStride,
                     const std::int32_t* index, int floats, int rows, int prefetchRows) {
    HWY_DYNAMIC_DISPATCH(AddGatheredRowsImpl)
    (to, toStride, from, fromStride, index, floats, rows, prefetchRows);
}

void extendRows(const IntervalRows& nearA, const IntervalRows& farA, const IntervalRows& nearB,
                const IntervalRows& farB, bool twoPaths, IntervalRowsOut out, int y0, int y1) {
    HWY_DYNAMIC_DISPATCH(ExtendRowsImpl)(nearA, farA, nearB, farB, twoPaths, out, y0, y1);
}

void mergeRows(bool odd, const MergeSide& side0, const MergeSide& side1, float second,
               float nearSecond, const float* nearRows, std::uint16_t* const out[3], int y0,
               int y1) {
    HWY_DYNAMIC_DISPATCH(MergeRowsImpl)
    (odd, side0, side1, second, nearSecond, nearRows, out, y0, y1);
}

}  // namespace luxel::gi2d::hrc
#endif
