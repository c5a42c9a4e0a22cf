// Auto exposure (--exposure auto) and the clipped-pixel measure behind the blown-out warning.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/core/tonemap.h"

namespace luxel {
namespace {

// A dark room lit by a gradient: pixel i of 1000 has value scale * (i + 1) / 1000.
Image ramp(float scale) {
    Image image(100, 10, 3);
    for (int y = 0; y < 10; ++y) {
        for (int x = 0; x < 100; ++x) {
            const float v = scale * static_cast<float>(y * 100 + x + 1) / 1000.0f;
            image.setRgb(x, y, Rgb(v, 0.5f * v, 0.25f * v));
        }
    }
    return image;
}

TEST(AutoExposure, TheNinetyNinthPercentileLandsAtNinetyPercentOfWhite) {
    for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::Reinhard, ToneCurve::Aces}) {
        const Image hdr = ramp(3.0f);
        const float stops = autoExposureStops(hdr, curve);
        // The 99th percentile of the red channel (the brightest) of 1000 pixels: index 989.
        const float p99 = 3.0f * 990.0f / 1000.0f;
        Image probe(1, 1, 3);
        probe.setRgb(0, 0, Rgb(p99));
        const Image shown = toneMap(probe, {stops, curve});
        EXPECT_NEAR(shown.at(0, 0, 0), kAutoExposureWhite, 1e-3) << static_cast<int>(curve);
        // Less than 2% of the pixels reach white.
        EXPECT_LT(clippedFraction(toneMap(hdr, {stops, curve})), 0.02);
    }
}

TEST(AutoExposure, AHundredTimesBrighterGetsAHundredTimesLessExposure) {
    const float base = autoExposureStops(ramp(1.0f), ToneCurve::Aces);
    const float bright = autoExposureStops(ramp(100.0f), ToneCurve::Aces);
    EXPECT_NEAR(std::exp2(base - bright), 100.0, 0.5) << base << " vs " << bright;
}

TEST(AutoExposure, DarkPixelsAndNonFiniteValuesDoNotCount) {
    Image hdr = ramp(2.0f);
    const float lit = autoExposureStops(hdr, ToneCurve::Aces);
    // Twice as many pixels, the new ones black, NaN or infinite: the lit ones decide.
    Image padded(200, 10, 3);
    for (int y = 0; y < 10; ++y) {
        for (int x = 0; x < 100; ++x) padded.setRgb(x, y, hdr.rgb(x, y));
        for (int x = 100; x < 200; ++x) {
            const float v = x % 3 == 0 ? NAN : (x % 3 == 1 ? INFINITY : 0.0f);
            padded.setRgb(x, y, Rgb(v));
        }
    }
    EXPECT_NEAR(autoExposureStops(padded, ToneCurve::Aces), lit, 0.02);
    EXPECT_EQ(autoExposureStops(Image(4, 4, 3), ToneCurve::Aces), 0.0f);  // no light at all
    EXPECT_EQ(autoExposureStops(Image(), ToneCurve::Aces), 0.0f);
}

TEST(ClippedFraction, CountsPixelsAtEightBitWhiteAndSkipsIgnoredOnes) {
    Image display(4, 1, 3);
    display.setRgb(0, 0, Rgb(1.0f, 0.0f, 0.0f));  // one channel at white is clipped
    display.setRgb(1, 0, Rgb(0.5f));
    display.setRgb(2, 0, Rgb(0.99f));  // encodes as 254: not clipped
    display.setRgb(3, 0, Rgb(1.0f));
    EXPECT_DOUBLE_EQ(clippedFraction(display), 0.5);
    Image ignore(4, 1, 3);
    ignore.setRgb(3, 0, Rgb(1.0f));
    EXPECT_DOUBLE_EQ(clippedFraction(display, &ignore), 1.0 / 3.0);
    EXPECT_GT(displayWhiteLevel(), 0.99f);
    EXPECT_LT(displayWhiteLevel(), 1.0f);
}

}  // namespace
}  // namespace luxel
