// Highway implementation of finishRow, compiled once per SIMD target; finishPixels is its scalar
// twin.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gi2d/hrc/finish_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// foreach_target.h re-includes this file per target; highway.h must follow it.
#include <hwy/highway.h>

#include "gi2d/hrc/finish_rows.h"
#include "gpu/shaders/shared/hrc_kernels.h"

#if HWY_ONCE
namespace luxel::gi2d::hrc {

void finishPixels(const FinishRow& row, int x0, int x1, float* out) {
    namespace shared = gpu::shared;
    auto at = [](const float* p) { return shared::vec3(p[0], p[1], p[2]); };
    for (int x = x0; x < x1; ++x) {
        const int i = 3 * x;
        shared::vec3 arriving = at(row.current + i);
        if (row.blur) {
            // Centre weight 4, neighbours 1 where the opacity gate lets them in.
            const float centre = row.opacityHere[x];
            shared::vec3 sum = arriving * 4.0f;
            float weight = 4.0f;
            auto take = [&](const float* pixel, float opacity) {
                if (!shared::hrcBlurTakes(centre, opacity)) return;
                sum += at(pixel);
                weight += 1.0f;
            };
            if (x > 0) take(row.current + i - 3, row.opacityHere[x - 1]);
            if (x + 1 < row.width) take(row.current + i + 3, row.opacityHere[x + 1]);
            if (row.above != nullptr) take(row.above + i, row.opacityAbove[x]);
            if (row.below != nullptr) take(row.below + i, row.opacityBelow[x]);
            arriving = sum * (1.0f / weight);
        }
        const shared::vec3 f = shared::hrcFinishPixelThrough(
            at(row.transmittance + i), at(row.emission + i), arriving, row.frustums);
        out[i] = f.x, out[i + 1] = f.y, out[i + 2] = f.z;
    }
}

}  // namespace luxel::gi2d::hrc
#endif

HWY_BEFORE_NAMESPACE();
namespace luxel::gi2d::hrc {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

struct Rgb3 {
    VF c[3];
};

HWY_INLINE Rgb3 LoadRgb(const float* p) {
    const DF df;
    Rgb3 v;
    hn::LoadInterleaved3(df, p, v.c[0], v.c[1], v.c[2]);
    return v;
}

void FinishRowImpl(const FinishRow& row, float* out) {
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const int w = row.width;
    const VF one = hn::Set(df, 1.0f), four = hn::Set(df, 4.0f);
    const VF gate = hn::Set(df, LUXEL_HRC_BLUR_GATE);
    const VF own = hn::Set(df, LUXEL_HRC_QUARTER_TURN * row.frustums);
    const VF invTwoPi = hn::Set(df, LUXEL_HRC_INV_TWO_PI);
    // Pixel 0 has no left neighbour and the last no right one: they go one at a time.
    finishPixels(row, 0, w < 1 ? 0 : 1, out);
    int x = 1;
    for (; x + lanes < w; x += lanes) {
        Rgb3 arriving = LoadRgb(row.current + 3 * x);
        if (row.blur) {
            const VF centre = hn::LoadU(df, row.opacityHere + x);
            Rgb3 sum;
            for (int c = 0; c < 3; ++c) sum.c[c] = hn::Mul(arriving.c[c], four);
            VF weight = four;
            // hrcBlurTakes: !(|n - centre| > gate), NaN taken as in the scalar code.
            auto take = [&](const float* pixel, const float* opacity) {
                const auto takes =
                    hn::Not(hn::Gt(hn::Abs(hn::Sub(hn::LoadU(df, opacity), centre)), gate));
                const Rgb3 n = LoadRgb(pixel);
                for (int c = 0; c < 3; ++c) {
                    sum.c[c] = hn::IfThenElse(takes, hn::Add(sum.c[c], n.c[c]), sum.c[c]);
                }
                weight = hn::IfThenElse(takes, hn::Add(weight, one), weight);
            };
            take(row.current + 3 * (x - 1), row.opacityHere + x - 1);
            take(row.current + 3 * (x + 1), row.opacityHere + x + 1);
            if (row.above != nullptr) take(row.above + 3 * x, row.opacityAbove + x);
            if (row.below != nullptr) take(row.below + 3 * x, row.opacityBelow + x);
            const VF inverse = hn::Div(one, weight);
            for (int c = 0; c < 3; ++c) arriving.c[c] = hn::Mul(sum.c[c], inverse);
        }
        // hrcFinishPixelThrough: (E (1 - T) (pi/2 frustums) + T arriving) / 2 pi.
        const Rgb3 t = LoadRgb(row.transmittance + 3 * x);
        const Rgb3 e = LoadRgb(row.emission + 3 * x);
        VF f[3];
        for (int c = 0; c < 3; ++c) {
            const VF emitted = hn::Mul(e.c[c], hn::Sub(one, t.c[c]));
            f[c] =
                hn::Mul(hn::Add(hn::Mul(emitted, own), hn::Mul(t.c[c], arriving.c[c])), invTwoPi);
        }
        hn::StoreInterleaved3(f[0], f[1], f[2], df, out + 3 * x);
    }
    finishPixels(row, x, w, out);
}

}  // namespace HWY_NAMESPACE
}  // namespace luxel::gi2d::hrc
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace luxel::gi2d::hrc {

HWY_EXPORT(FinishRowImpl);

void finishRow(const FinishRow& row, float* out) {
    HWY_DYNAMIC_DISPATCH(FinishRowImpl)(row, out);
}

}  // namespace luxel::gi2d::hrc
#endif
