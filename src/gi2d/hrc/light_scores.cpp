// Highway implementation of lightScoreRow, compiled once per SIMD target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gi2d/hrc/light_scores.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// foreach_target.h re-includes this file per target; highway.h must follow it.
#include <hwy/highway.h>

#include <algorithm>

#include "gi2d/hrc/light_scores.h"

HWY_BEFORE_NAMESPACE();
namespace luxel::gi2d::hrc {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

// std::max(a, b) and std::min(a, b) lane by lane: (a < b) ? b : a and (b < a) ? b : a.
HWY_INLINE VF StdMax(VF a, VF b) {
    return hn::IfThenElse(hn::Lt(a, b), b, a);
}
HWY_INLINE VF StdMin(VF a, VF b) {
    return hn::IfThenElse(hn::Lt(b, a), b, a);
}

float LightScoreRowImpl(const float* emission, const float* sigma, int width, float* scores) {
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const VF one = hn::Set(df, 1.0f);
    VF most = hn::Zero(df);
    int x = 0;
    for (; x + lanes <= width; x += lanes) {
        VF e[3], s[3];
        hn::LoadInterleaved3(df, emission + 3 * x, e[0], e[1], e[2]);
        hn::LoadInterleaved3(df, sigma + 3 * x, s[0], s[1], s[2]);
        VF c[3];
        for (int k = 0; k < 3; ++k) c[k] = hn::Mul(e[k], StdMin(s[k], one));
        const VF score = StdMax(c[0], StdMax(c[1], c[2]));
        hn::StoreU(score, df, scores + x);
        most = StdMax(most, score);
    }
    // The lanes' maxima, then the rest of the row: NaN never enters, so the largest value is
    // the same in any order.
    HWY_ALIGN float lane[hn::MaxLanes(df)];
    hn::Store(most, df, lane);
    float result = 0.0f;
    for (int i = 0; i < lanes; ++i) result = std::max(result, lane[i]);
    for (; x < width; ++x) {
        const float* e = emission + 3 * x;
        const float* s = sigma + 3 * x;
        const float r = e[0] * std::min(s[0], 1.0f), g = e[1] * std::min(s[1], 1.0f),
                    b = e[2] * std::min(s[2], 1.0f);
        scores[x] = std::max(r, std::max(g, b));
        result = std::max(result, scores[x]);
    }
    return result;
}

}  // namespace HWY_NAMESPACE
}  // namespace luxel::gi2d::hrc
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace luxel::gi2d::hrc {

HWY_EXPORT(LightScoreRowImpl);

float lightScoreRow(const float* emission, const float* sigma, int width, float* scores) {
    return HWY_DYNAMIC_DISPATCH(LightScoreRowImpl)(emission, sigma, width, scores);
}

}  // namespace luxel::gi2d::hrc
#endif
