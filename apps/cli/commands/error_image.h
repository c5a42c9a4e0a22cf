// Pictures of a solver's error for `luxel compare-solvers --error-image` (docs/solver-errors.md):
// a signed difference against the reference, as a fraction of the reference's mean, on a
// diverging colour scale.
#pragma once

#include <vector>

#include "luxel/core/image.h"

namespace luxel::cli {

// (value - reference) per pixel, averaged over the RGB channels, divided by `mean`.
Image signedRelativeDifference(const Image& value, const Image& reference, double mean);

// Colours of a signed image (linear RGB, for writePng): 0 is white, +scale and above pure red,
// -scale and below pure blue, linear in display values in between.
Image divergingColours(const Image& signedImage, double scale);

// Images of one size side by side with 4 px dark gaps.
Image sideBySide(const std::vector<Image>& images);

}  // namespace luxel::cli
