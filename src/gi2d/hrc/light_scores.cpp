// Highway implementation of lightScoreRow, compiled once per SIMD target, and the canvas of scores.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gi2d/hrc/light_scores.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// foreach_target.h re-includes this file per target; highway.h must follow it.
#include <hwy/highway.h>

#include <algorithm>
#include <limits>
#include <memory>

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

LightScoreRowScan LightScoreRowImpl(const float* emission, const float* sigma, int width,
                                    float* scores) {
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const VF one = hn::Set(df, 1.0f), zero = hn::Zero(df);
    VF most = zero;
    // sigma where above 0, else 0 (NaN too): the least of them is 0 as soon as one is not above 0,
    // and otherwise the least sigma, exactly (no NaN reaches Min).
    VF least = hn::Set(df, std::numeric_limits<float>::infinity());
    int x = 0;
    for (; x + lanes <= width; x += lanes) {
        VF e[3], s[3];
        hn::LoadInterleaved3(df, emission + 3 * x, e[0], e[1], e[2]);
        hn::LoadInterleaved3(df, sigma + 3 * x, s[0], s[1], s[2]);
        VF c[3];
        for (int k = 0; k < 3; ++k) {
            c[k] = hn::Mul(e[k], StdMin(s[k], one));
            least = hn::Min(least, hn::IfThenElseZero(hn::Gt(s[k], zero), s[k]));
        }
        const VF score = StdMax(c[0], StdMax(c[1], c[2]));
        hn::StoreU(score, df, scores + x);
        most = StdMax(most, score);
    }
    // The lanes' extremes, then the rest of the row: NaN never enters, so the largest score and
    // the least sigma are the same in any order.
    HWY_ALIGN float lane[hn::MaxLanes(df)];
    HWY_ALIGN float low[hn::MaxLanes(df)];
    hn::Store(most, df, lane);
    hn::Store(least, df, low);
    LightScoreRowScan scan;
    scan.leastSigma = std::numeric_limits<float>::infinity();
    for (int i = 0; i < lanes; ++i) {
        scan.brightest = std::max(scan.brightest, lane[i]);
        scan.leastSigma = std::min(scan.leastSigma, low[i]);
    }
    for (; x < width; ++x) {
        const float* e = emission + 3 * x;
        const float* s = sigma + 3 * x;
        const float r = e[0] * std::min(s[0], 1.0f), g = e[1] * std::min(s[1], 1.0f),
                    b = e[2] * std::min(s[2], 1.0f);
        scores[x] = std::max(r, std::max(g, b));
        scan.brightest = std::max(scan.brightest, scores[x]);
        for (int k = 0; k < 3; ++k)
            scan.leastSigma = std::min(scan.leastSigma, s[k] > 0 ? s[k] : 0);
    }
    return scan;
}

}  // namespace HWY_NAMESPACE
}  // namespace luxel::gi2d::hrc
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "gi2d/hrc/emitting_pixels.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {

HWY_EXPORT(LightScoreRowImpl);

LightScoreRowScan lightScoreRow(const float* emission, const float* sigma, int width,
                                float* scores) {
    return HWY_DYNAMIC_DISPATCH(LightScoreRowImpl)(emission, sigma, width, scores);
}

Result<LightScores> LightScores::checkedOf(const Medium2D& medium, bool emitting) {
    const int w = medium.width(), h = medium.height();
    if (Status s =
            checkMemory(bytesFor(w, h, emitting),
                        "HRC's light scores at " + std::to_string(w) + "x" + std::to_string(h));
        !s) {
        return s.error();
    }
    return of(medium, emitting);
}

LightScores LightScores::of(const Medium2D& medium, bool emitting) {
    LightScores scores;
    const int w = medium.width(), h = medium.height();
    scores.width_ = w;
    scores.height_ = h;
    // Not zeroed first: the rows' scans write every score and code, each row's pages on the
    // thread that scans it.
    const std::size_t pixels = static_cast<std::size_t>(w) * h;
    scores.scores_ = std::make_unique_for_overwrite<float[]>(pixels);
    if (emitting) scores.emitting_ = std::make_unique_for_overwrite<std::uint8_t[]>(pixels);
    scores.rows_.resize(static_cast<std::size_t>(h));
    const float* e = medium.emission.data();
    const float* sigma = medium.absorption.data();
    std::uint8_t* const codes = scores.emitting_.get();
    parallelForRange(h, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            const std::size_t base = static_cast<std::size_t>(y) * w;
            scores.rows_[static_cast<std::size_t>(y)] =
                lightScoreRow(e + base * 3, sigma + base * 3, w, scores.scores_.get() + base);
            if (codes != nullptr) emittingRow(e + base * 3, sigma + base * 3, w, codes + base);
        }
    });
    return scores;
}

void LightScores::rescoreRows(const Medium2D& medium, int y0, int y1) {
    const float* emission = medium.emission.data();
    const float* sigma = medium.absorption.data();
    parallelForRange(y1 - y0, 16, [&](int begin, int end) {
        for (int y = y0 + begin; y < y0 + end; ++y) {
            const std::size_t base = static_cast<std::size_t>(y) * width_;
            rows_[static_cast<std::size_t>(y)] =
                lightScoreRow(emission + base * 3, sigma + base * 3, width_, scores_.get() + base);
        }
    });
}

void LightScores::release() {
    scores_.reset();
    emitting_.reset();  // where no search took them (a canvas without lights)
}

float LightScores::brightest() const {
    float most = 0.0f;
    for (const LightScoreRowScan& r : rows_) most = std::max(most, r.brightest);
    return most;
}

float LightScores::leastAbsorption() const {
    if (rows_.empty()) return 0.0f;
    float least = rows_.front().leastSigma;
    for (const LightScoreRowScan& r : rows_) least = std::min(least, r.leastSigma);
    return least;
}

std::uint64_t LightScores::bytesFor(int width, int height, bool emitting) {
    return static_cast<std::uint64_t>(width) * height * (sizeof(float) + (emitting ? 1 : 0)) +
           static_cast<std::uint64_t>(height) * sizeof(LightScoreRowScan);
}

}  // namespace luxel::gi2d::hrc
#endif
