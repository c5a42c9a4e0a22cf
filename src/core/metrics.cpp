// Image comparison metrics: RMSE, relative L1 and maximum absolute error, optionally masked.
#include "luxel/core/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace luxel {

namespace {

std::string describeSize(const Image& image) {
    return std::to_string(image.width()) + "x" + std::to_string(image.height()) + " with " +
           std::to_string(image.channels()) + (image.channels() == 1 ? " channel" : " channels");
}

}  // namespace

Result<ImageErrors> compareImages(const Image& a, const Image& b, const Image* mask) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels()) {
        return Error("cannot compare images of different sizes: " + describeSize(a) + " vs " +
                     describeSize(b) + " (reference)");
    }
    if (mask != nullptr &&
        (mask->width() != b.width() || mask->height() != b.height() || mask->channels() != 1)) {
        return Error("the mask must be a 1-channel image of the images' size: mask is " +
                     describeSize(*mask) + ", images are " + describeSize(b));
    }

    const int channels = b.channels();
    const std::size_t pixels = b.pixelCount();
    const float* pa = a.data();
    const float* pb = b.data();
    double sumSquared = 0, sumAbsDiff = 0, sumAbsRef = 0, sumRef = 0, maxAbs = 0;
    std::size_t counted = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        if (mask != nullptr && !(mask->data()[i] > 0.5f)) continue;
        ++counted;
        const std::size_t base = i * static_cast<std::size_t>(channels);
        for (int c = 0; c < channels; ++c) {
            const double va = pa[base + c];
            const double vb = pb[base + c];
            const double diff = std::abs(va - vb);
            sumSquared += diff * diff;
            sumAbsDiff += diff;
            sumAbsRef += std::abs(vb);
            sumRef += vb;
            maxAbs = std::max(maxAbs, diff);
        }
    }

    ImageErrors errors;
    errors.countedPixels = counted;
    if (counted == 0) return errors;
    const double values = static_cast<double>(counted) * channels;
    errors.rmse = std::sqrt(sumSquared / values);
    // Both means share the count, so the ratio of sums is the ratio of means.
    if (sumAbsRef > 0) {
        errors.relativeL1 = sumAbsDiff / sumAbsRef;
    } else {
        errors.relativeL1 = sumAbsDiff > 0 ? std::numeric_limits<double>::infinity() : 0.0;
    }
    errors.maxAbsError = maxAbs;
    errors.meanReference = sumRef / values;
    return errors;
}

}  // namespace luxel
