// Small images for the post-processing tests.
#pragma once

#include <cmath>

#include "luxel/core/image.h"

namespace luxel::test {

// HDR noise: per channel exp(4u - 2) for u uniform in [0, 1), so values span e^-2..e^2 with
// occasional bright texels.
inline Image randomHdr(int w, int h, std::uint64_t seed) {
    Image image(w, h, 3);
    std::uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
    for (std::size_t i = 0; i < image.size(); ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const double u = static_cast<double>(state >> 11) * 0x1.0p-53;
        image.data()[i] = static_cast<float>(std::exp(4.0 * u - 2.0));
    }
    return image;
}

inline double meanOf(const Image& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    return sum / static_cast<double>(image.size());
}

}  // namespace luxel::test
