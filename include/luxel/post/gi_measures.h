// Measures of a global illumination solver's image against a reference that plain error
// metrics miss (docs/voxel-gi-measures.md): light leaking into places the reference keeps dark,
// and flicker of the low-frequency image when the sun moves. All images are linear, and a
// solver's image and its reference have the same size and channel count.
#pragma once

#include <cstddef>
#include <span>

#include "luxel/core/error.h"
#include "luxel/core/image.h"

namespace luxel::post {

// Pixels per side of the low-frequency blocks: the scale a smooth GI method is judged at.
inline constexpr int kLowFrequencyBlock = 8;

// The mean of each block x block square of `image` (partial blocks at the right and bottom
// edges too), one pixel per block, the channels kept. `block` >= 1.
Image blockMeans(const Image& image, int block = kLowFrequencyBlock);

// Where the reference's low-frequency image is dark: a block whose reference brightness (the mean
// of its channels) is below this fraction of the reference image's mean brightness.
inline constexpr double kDarkFraction = 0.1;

struct DarkLeak {
    double referenceMean = 0;  // m: the reference image's mean brightness
    std::size_t darkBlocks = 0, blocks = 0;
    double referenceDark = 0;  // the reference's mean brightness over the dark blocks
    double solverDark = 0;     // the solver's, over the same blocks
    // (solverDark - referenceDark) / m: light the solver adds where the reference is dark, as a
    // fraction of the image's mean; 0 with no dark blocks (or a black reference).
    double leak = 0;
};

// The leak of `solver` against `reference` over the kLowFrequencyBlock blocks whose reference
// brightness is below darkFraction x the reference mean. Fails on different sizes or channels.
Result<DarkLeak> darkRegionLeak(const Image& solver, const Image& reference,
                                double darkFraction = kDarkFraction);

struct SunFlicker {
    double referenceMean = 0;    // m: the reference's mean over all frames, pixels, channels
    double referenceChange = 0;  // mean over frame pairs of mean |dR| over blocks, over m
    // Mean over frame pairs k of mean over blocks and channels of |dS_k - dR_k|, over m, where
    // dX_k = blockMeans(X_{k+1}) - blockMeans(X_k): the frame-to-frame change of the solver's
    // low-frequency image that the reference's change does not have.
    double flicker = 0;
};

// The flicker of `solver` frames against `reference` frames of the same scene under the same
// sequence of sun directions. Fails unless both have the same number (>= 2) of frames, all of
// one size and channel count.
Result<SunFlicker> sunFlicker(std::span<const Image> solver, std::span<const Image> reference);

}  // namespace luxel::post
