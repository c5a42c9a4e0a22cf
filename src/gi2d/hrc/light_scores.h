// The light score per pixel (docs/algorithms/holographic-radiance-cascades.md §12.3), a row at a
// time with Highway vectors, and the canvas of them that a solve computes once: the compact
// lights' search (§12.5), the near-light mask and the exact near field's plan (§12.3) all read it.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

// What one pass over a row gives besides its scores.
struct LightScoreRowScan {
    float brightest = 0;  // std::max of the scores from 0
    // The least absorption over the row's pixels and channels, 0 where some is not above 0 (NaN
    // included): what bounds the rays of §12.3's near field.
    float leastSigma = 0;
};

// scores[x] = max_c E_c min(sigma_c, 1) for the `width` RGB pixels of a row (max and min as
// std::max and std::min take them, NaN included).
LightScoreRowScan lightScoreRow(const float* emission, const float* sigma, int width,
                                float* scores);

// A pixel is a light where its score is at least this, 1/64 of the brightest pixel's (§12.3):
// the near-light mask, the exact near field and the compact lights tell the lights alike.
inline float lightScoreThreshold(float brightest) {
    return brightest / 64.0f;
}

// Every pixel's score, once per solve (rows in parallel), and what the rows' scans found.
class LightScores {
  public:
    // With `emitting`, each pixel's emittingRow code too (emitting_pixels.h), for the compact
    // lights' search (§12.5), made row by row right after the scores, while the row's medium is
    // still in the cache.
    static LightScores of(const Medium2D& medium, bool emitting = false);
    // `of`, after checking that its bytes fit in memory (a solve's first buffer, on both backends).
    static Result<LightScores> checkedOf(const Medium2D& medium, bool emitting);
    // Scores rows [y0, y1) again from `medium`, whose emission changed there alone (the split of
    // §12.5 hands the cascades a medium without the compact lights' emission).
    void rescoreRows(const Medium2D& medium, int y0, int y1);
    // Frees the scores once the mask and the plan are made (the sweep's rings come after).
    void release();
    // The emitting codes, a byte per pixel, handed over (null where not made or taken already).
    std::unique_ptr<std::uint8_t[]> takeEmitting() { return std::move(emitting_); }

    int width() const { return width_; }
    int height() const { return height_; }
    const float* row(int y) const { return scores_.get() + static_cast<std::size_t>(y) * width_; }
    float at(std::size_t i) const { return scores_[i]; }
    float rowBrightest(int y) const { return rows_[static_cast<std::size_t>(y)].brightest; }
    float brightest() const;  // over the canvas, 0 for one without emission
    // The least absorption of any pixel and channel where all are above 0; 0 where some is not
    // (then nothing bounds a ray, §12.3's near field).
    float leastAbsorption() const;

    // Bytes of the scores, and of the emitting codes with them where `emitting`.
    static std::uint64_t bytesFor(int width, int height, bool emitting = false);

  private:
    int width_ = 0, height_ = 0;
    std::unique_ptr<float[]> scores_;  // written by the rows' scans before any read
    std::unique_ptr<std::uint8_t[]> emitting_;
    std::vector<LightScoreRowScan> rows_;
};

}  // namespace luxel::gi2d::hrc
