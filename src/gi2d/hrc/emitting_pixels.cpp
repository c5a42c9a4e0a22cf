// Highway implementation of emittingRow, compiled once per SIMD target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gi2d/hrc/emitting_pixels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// foreach_target.h re-includes this file per target; highway.h must follow it.
#include <hwy/highway.h>

#include "gi2d/hrc/emitting_pixels.h"

HWY_BEFORE_NAMESPACE();
namespace luxel::gi2d::hrc {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

int EmittingRowImpl(const float* emission, const float* sigma, int width, std::uint8_t* state) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const hn::Rebind<std::uint8_t, decltype(di)> du8;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const auto zero = hn::Zero(df);
    const auto sureE = hn::Set(df, kSureEmission), sureSigma = hn::Set(df, kSureAbsorption);
    const auto one = hn::Set(di, 1), two = hn::Set(di, 2);
    int unsure = 0;
    int x = 0;
    for (; x + lanes <= width; x += lanes) {
        hn::Vec<decltype(df)> e[3], s[3];
        hn::LoadInterleaved3(df, emission + 3 * x, e[0], e[1], e[2]);
        hn::LoadInterleaved3(df, sigma + 3 * x, s[0], s[1], s[2]);
        auto sure = hn::Lt(zero, zero), signs = hn::Lt(zero, zero);  // all false
        for (int k = 0; k < 3; ++k) {
            sure = hn::Or(sure, hn::And(hn::Ge(e[k], sureE), hn::Ge(s[k], sureSigma)));
            signs = hn::Or(signs, hn::Or(hn::And(hn::Gt(e[k], zero), hn::Gt(s[k], zero)),
                                         hn::And(hn::Lt(e[k], zero), hn::Lt(s[k], zero))));
        }
        const auto maybe = hn::AndNot(sure, signs);
        unsure += static_cast<int>(hn::CountTrue(df, maybe));
        const auto code = hn::IfThenElse(hn::RebindMask(di, sure), one,
                                         hn::IfThenElseZero(hn::RebindMask(di, maybe), two));
        hn::StoreU(hn::DemoteTo(du8, code), du8, state + x);
    }
    for (; x < width; ++x) {
        bool sure = false, signs = false;
        for (int k = 0; k < 3; ++k) {
            const float e = emission[3 * x + k], s = sigma[3 * x + k];
            sure = sure || (e >= kSureEmission && s >= kSureAbsorption);
            signs = signs || (e > 0 && s > 0) || (e < 0 && s < 0);
        }
        state[x] = sure ? 1 : signs ? 2 : 0;
        unsure += !sure && signs ? 1 : 0;
    }
    return unsure;
}

}  // namespace HWY_NAMESPACE
}  // namespace luxel::gi2d::hrc
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace luxel::gi2d::hrc {

HWY_EXPORT(EmittingRowImpl);

int emittingRow(const float* emission, const float* sigma, int width, std::uint8_t* state) {
    return HWY_DYNAMIC_DISPATCH(EmittingRowImpl)(emission, sigma, width, state);
}

}  // namespace luxel::gi2d::hrc
#endif
