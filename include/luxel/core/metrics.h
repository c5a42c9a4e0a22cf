// Image comparison metrics. All take a test image `a` and a reference `b` of the same size and
// channel count, and an optional mask (1 channel, same size; pixels with mask > 0.5 count).
#pragma once

#include "luxel/core/error.h"
#include "luxel/core/image.h"

namespace luxel {

struct ImageErrors {
    double rmse = 0;           // sqrt(mean((a - b)^2)) over counted pixels and channels
    double relativeL1 = 0;     // mean|a - b| / mean|b|; 0 if both are all zero, inf if only b is
    double maxAbsError = 0;    // max |a - b|
    double meanReference = 0;  // mean of b (for reading RMSE as a fraction)
    std::size_t countedPixels = 0;
};

// Fails (clear message) when sizes or channels differ, or the mask has the wrong size.
Result<ImageErrors> compareImages(const Image& a, const Image& b, const Image* mask = nullptr);

}  // namespace luxel
