// The near-light mask's light score per pixel (docs/algorithms/holographic-radiance-cascades.md
// §12.3), a row at a time with Highway vectors: the mask scans every pixel twice per solve.
#pragma once

namespace luxel::gi2d::hrc {

// scores[x] = max_c E_c min(sigma_c, 1) for the `width` RGB pixels of a row (max and min as
// std::max and std::min take them, NaN included); returns the largest, std::max over the row
// from 0.
float lightScoreRow(const float* emission, const float* sigma, int width, float* scores);

// A pixel is a light where its score is at least this, 1/64 of the brightest pixel's (§12.3):
// the near-light mask and the exact near field tell the lights alike.
inline float lightScoreThreshold(float brightest) {
    return brightest / 64.0f;
}

}  // namespace luxel::gi2d::hrc
