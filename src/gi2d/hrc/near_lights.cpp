// The near-light mask of §12.3: lights found by their emitted power, then a distance transform
// of radius 3 px, separable in squared distances (rows first, then the five rows around).
#include "gi2d/hrc/near_lights.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "gi2d/hrc/light_scores.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {
namespace {

// Rows per task; each task also scans the two rows on either side of its own.
constexpr int kGrain = 32;
// Squared distances from 9 (3 px) on keep the whole blend.
constexpr int kFar = 9;

// The kept fraction in 64ths for a squared pixel-centre distance below 9: none within 1 px, the
// whole from 3 px, linear in the distance between (§12.3's best trial).
constexpr std::array<std::uint8_t, kFar + 1> keptTable() {
    // round(64 clamp((sqrt(d2) - 1) / 2, 0, 1)) for d2 = 0 .. 9 (3, 6 and 7 are no sums of
    // two squares; they are never looked up).
    return {0, 0, 13, 32, 32, 40, 40, 40, 59, 64};
}

}  // namespace

std::uint64_t NearLightMask::bytesFor(int width, int height) {
    return (static_cast<std::uint64_t>(width) * height + 3) / 4 * 4;
}

std::uint64_t NearLightMask::hostBytesFor(int width, int height) {
    return bytesFor(width, height) + static_cast<std::uint64_t>(width) + height;
}

NearLightMask NearLightMask::fromMedium(const Medium2D& medium) {
    return fromScores(LightScores::of(medium));
}

NearLightMask NearLightMask::fromScores(const LightScores& scores) {
    NearLightMask mask;
    mask.build(scores);
    return mask;
}

void NearLightMask::build(const LightScores& scores) {
    NearLightMask& mask = *this;
    const int w = scores.width(), h = scores.height();
    mask.width_ = w;
    mask.height_ = h;
    mask.bytes_.assign(bytesFor(w, h), 64);
    mask.columnNear_.assign(static_cast<std::size_t>(w), 0);
    mask.rowNear_.assign(static_cast<std::size_t>(h), 0);
    const float brightest = scores.brightest();
    if (!(brightest > 0.0f)) return;
    const float threshold = lightScoreThreshold(brightest);
    static constexpr std::array<std::uint8_t, kFar + 1> kept = keptTable();
    parallelForRange(h, kGrain, [&, w, h, threshold](int y0, int y1) {
        // Per row of [y0 - 2, y1 + 2): the squared distance along the row to the nearest light,
        // capped at 9. The byte loops run through raw pointers and copies of the sizes: a byte
        // store may alias anything reached by reference (a vector's own pointer, the width),
        // which kept the compiler from vectorising them.
        auto lit = [&](int y) { return scores.rowBrightest(y) >= threshold; };
        const int r0 = std::max(0, y0 - 2), r1 = std::min(h, y1 + 2);
        std::vector<std::uint8_t> along(static_cast<std::size_t>(r1 - r0) * w, kFar);
        std::vector<std::uint8_t> lights(static_cast<std::size_t>(w) + 4, 0);  // 2 unlit each side
        for (int y = r0; y < r1; ++y) {
            if (!lit(y)) continue;
            std::uint8_t* row = along.data() + static_cast<std::size_t>(y - r0) * w;
            std::uint8_t* const l = lights.data() + 2;
            const float* const score = scores.row(y);
            for (int x = 0; x < w; ++x) l[x] = score[x] >= threshold ? 1 : 0;
            // The distance to the nearest light in the row, capped at 3, squared.
            for (int x = 0; x < w; ++x) {
                row[x] = l[x] ? 0 : (l[x - 1] | l[x + 1]) ? 1 : (l[x - 2] | l[x + 2]) ? 4 : kFar;
            }
        }
        // Then the least over the five rows around of along^2 + dy^2 (a loop over bytes the
        // compiler vectorises), and the kept fraction from it.
        std::vector<std::uint8_t> d2(lights.size());  // the first w bytes are used
        for (int y = y0; y < y1; ++y) {
            bool near = false;  // rows with no light within 2 rows keep the whole blend
            for (int r = std::max(0, y - 2); r <= std::min(h - 1, y + 2); ++r)
                near = near || lit(r);
            if (!near) continue;
            std::uint8_t* const least = d2.data();
            std::fill_n(least, w, static_cast<std::uint8_t>(kFar));
            for (int r = std::max(r0, y - 2); r <= std::min(r1 - 1, y + 2); ++r) {
                const std::uint8_t* a = along.data() + static_cast<std::size_t>(r - r0) * w;
                const auto dy2 = static_cast<std::uint8_t>((r - y) * (r - y));
                for (int x = 0; x < w; ++x) {
                    least[x] = std::min(least[x], static_cast<std::uint8_t>(a[x] + dy2));
                }
            }
            std::uint8_t* const out = mask.bytes_.data() + static_cast<std::size_t>(y) * w;
            std::uint8_t any = 0;
            for (int x = 0; x < w; ++x) {
                out[x] = kept[least[x]];
                any |= out[x] < 64 ? 1 : 0;
            }
            mask.rowNear_[static_cast<std::size_t>(y)] = any;
        }
    });
    // A column is near where some row's pixel in it is (the rows that are, usually few).
    std::uint8_t* const near = mask.columnNear_.data();
    for (int y = 0; y < h; ++y) {
        if (!mask.rowNear(y)) continue;
        const std::uint8_t* row = mask.bytes_.data() + static_cast<std::size_t>(y) * w;
        for (int x = 0; x < w; ++x) near[x] |= row[x] < 64 ? 1 : 0;
    }
}

}  // namespace luxel::gi2d::hrc
