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

// keptTable()[d2] as a sum of masked steps, which the compiler vectorises (a byte table lookup,
// or a chain of selects, it does not).
constexpr std::uint8_t keptOf(std::uint8_t d2) {
    auto step = [d2](int from, int by) {
        return static_cast<std::uint8_t>(static_cast<std::uint8_t>(-static_cast<int>(d2 >= from)) &
                                         by);
    };
    return static_cast<std::uint8_t>(step(2, 13) + step(3, 19) + step(5, 8) + step(8, 19) +
                                     step(9, 5));
}

constexpr bool keptOfMatchesTheTable() {
    for (int d2 = 0; d2 <= kFar; ++d2) {
        if (keptOf(static_cast<std::uint8_t>(d2)) != keptTable()[static_cast<std::size_t>(d2)]) {
            return false;
        }
    }
    return true;
}
static_assert(keptOfMatchesTheTable());

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
    parallelForRange(h, kGrain, [&](int y0, int y1) {
        // Per row of [y0 - 2, y1 + 2): the squared distance along the row to the nearest light,
        // capped at 9. The byte loops run through raw pointers and local copies of the sizes and
        // the threshold: a byte store may alias anything reached through a pointer (a vector's
        // own, the closure's captures), which kept the compiler from vectorising them.
        const int width = w, rows = h;
        const float limit = threshold;
        auto lit = [&](int y) { return scores.rowBrightest(y) >= limit; };
        const int r0 = std::max(0, y0 - 2), r1 = std::min(rows, y1 + 2);
        std::vector<std::uint8_t> along(static_cast<std::size_t>(r1 - r0) * width, kFar);
        std::vector<std::uint8_t> lights(static_cast<std::size_t>(width) + 4,
                                         0);  // 2 unlit each side
        for (int y = r0; y < r1; ++y) {
            if (!lit(y)) continue;
            std::uint8_t* const row = along.data() + static_cast<std::size_t>(y - r0) * width;
            std::uint8_t* const l = lights.data() + 2;
            const float* const score = scores.row(y);
            for (int x = 0; x < width; ++x) l[x] = score[x] >= limit ? 1 : 0;
            // The distance to the nearest light in the row, capped at 3, squared (every load
            // made, so that the loop has no branches).
            for (int x = 0; x < width; ++x) {
                const std::uint8_t at = l[x], one = l[x - 1] | l[x + 1], two = l[x - 2] | l[x + 2];
                row[x] = at ? 0 : one ? 1 : two ? 4 : kFar;
            }
        }
        // Then the least over the five rows around of along^2 + dy^2, and the kept fraction
        // from it.
        std::vector<std::uint8_t> d2(lights.size());  // the first w bytes are used
        for (int y = y0; y < y1; ++y) {
            bool near = false;  // rows with no light within 2 rows keep the whole blend
            for (int r = std::max(0, y - 2); r <= std::min(rows - 1, y + 2); ++r)
                near = near || lit(r);
            if (!near) continue;
            std::uint8_t* const least = d2.data();
            std::fill_n(least, width, static_cast<std::uint8_t>(kFar));
            for (int r = std::max(r0, y - 2); r <= std::min(r1 - 1, y + 2); ++r) {
                const std::uint8_t* const a =
                    along.data() + static_cast<std::size_t>(r - r0) * width;
                const auto dy2 = static_cast<std::uint8_t>((r - y) * (r - y));
                for (int x = 0; x < width; ++x) {
                    least[x] = std::min(least[x], static_cast<std::uint8_t>(a[x] + dy2));
                }
            }
            std::uint8_t* const out = mask.bytes_.data() + static_cast<std::size_t>(y) * width;
            for (int x = 0; x < width; ++x) out[x] = keptOf(least[x]);
            std::uint8_t any = 0;  // some pixel keeps less than the whole: nearer than 3 px
            for (int x = 0; x < width; ++x) any |= static_cast<std::uint8_t>(least[x] < kFar);
            mask.rowNear_[static_cast<std::size_t>(y)] = any;
        }
    });
    // A column is near where some row's pixel in it is (the rows that are, usually few); the
    // width copied, as the closure above holds w's address.
    std::uint8_t* const near = mask.columnNear_.data();
    const int width = w;
    for (int y = 0; y < h; ++y) {
        if (!mask.rowNear(y)) continue;
        const std::uint8_t* row = mask.bytes_.data() + static_cast<std::size_t>(y) * width;
        for (int x = 0; x < width; ++x) near[x] |= row[x] < 64 ? 1 : 0;
    }
}

}  // namespace luxel::gi2d::hrc
