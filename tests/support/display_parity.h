// GPU-against-CPU image parity as a viewer sees it: both renders tone mapped (ACES) and sRGB
// encoded to 8 bits, compared channel by channel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "luxel/core/image.h"
#include "luxel/core/tonemap.h"

namespace luxel::test {

struct Parity {
    double differingPixels = 0;  // share of pixels with a channel off by more than the tolerance
    double meanAbs = 0;          // mean |difference| over all channels, in 1/255 units
    int maxAbs = 0;              // largest channel difference, in 1/255 units
};

// `tolerance` is the channel difference, in 1/255 units, that a pixel may show and still agree.
inline Parity compareDisplay(const Image& a, const Image& b, int tolerance = 1) {
    const Image ta = toneMap(a, {}), tb = toneMap(b, {});
    Parity p;
    long differing = 0;
    double sum = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const auto byte = [&](const Image& im) {
                    return static_cast<int>(std::lround(linearToSrgb(im.at(x, y, c)) * 255.0f));
                };
                const int d = std::abs(byte(ta) - byte(tb));
                worst = std::max(worst, d);
                sum += d;
            }
            differing += worst > tolerance;
            p.maxAbs = std::max(p.maxAbs, worst);
        }
    }
    p.differingPixels = static_cast<double>(differing) / a.pixelCount();
    p.meanAbs = sum / (3.0 * a.pixelCount());
    return p;
}

inline void printParity(const std::string& what, const Parity& p) {
    std::printf("%s: %.4f%% pixels differ by > 1/255, mean |diff| %.5f/255, max %d/255\n",
                what.c_str(), 100.0 * p.differingPixels, p.meanAbs, p.maxAbs);
}

}  // namespace luxel::test
