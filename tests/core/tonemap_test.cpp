// Tests for the tonemapping curves and the sRGB transfer curve.
#include "luxel/core/tonemap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace luxel {
namespace {

float mapOne(float value, ToneCurve curve, float stops = 0.0f) {
    Image image(1, 1, 1);
    image.at(0, 0, 0) = value;
    return toneMap(image, {stops, curve}).at(0, 0, 0);
}

TEST(TonemapTest, SrgbCurveKnownValues) {
    EXPECT_NEAR(linearToSrgb(0.5f), 0.7354f, 1e-4f);
    EXPECT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(linearToSrgb(1.0f), 1.0f);
    // The linear toe below 0.0031308.
    EXPECT_FLOAT_EQ(linearToSrgb(0.002f), 0.002f * 12.92f);
    EXPECT_NEAR(srgbToLinear(0.7354f), 0.5f, 1e-4f);
    EXPECT_FLOAT_EQ(srgbToLinear(0.04f), 0.04f / 12.92f);
    EXPECT_NEAR(srgbToLinear(188.0f / 255.0f), 0.5029f, 1e-4f);
}

TEST(TonemapTest, SrgbCurveInvertsAndIsContinuousAtTheJoin) {
    for (int i = 0; i <= 1000; ++i) {
        const float x = static_cast<float>(i) / 1000.0f;
        EXPECT_NEAR(srgbToLinear(linearToSrgb(x)), x, 2e-6f) << x;
    }
    EXPECT_NEAR(linearToSrgb(0.0031308f), linearToSrgb(0.0031309f), 1e-5f);
    EXPECT_NEAR(srgbToLinear(0.04045f), srgbToLinear(0.04046f), 1e-5f);
}

TEST(TonemapTest, SrgbCurveClampsAndMapsNanToZero) {
    EXPECT_EQ(linearToSrgb(-1.0f), 0.0f);
    EXPECT_EQ(linearToSrgb(5.0f), 1.0f);
    EXPECT_EQ(linearToSrgb(std::numeric_limits<float>::quiet_NaN()), 0.0f);
    EXPECT_EQ(srgbToLinear(std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(TonemapTest, ParseToneCurveAcceptsLowerCaseNamesOnly) {
    EXPECT_EQ(parseToneCurve("clamp"), ToneCurve::Clamp);
    EXPECT_EQ(parseToneCurve("reinhard"), ToneCurve::Reinhard);
    EXPECT_EQ(parseToneCurve("aces"), ToneCurve::Aces);
    EXPECT_FALSE(parseToneCurve("ACES").has_value());
    EXPECT_FALSE(parseToneCurve("").has_value());
    EXPECT_FALSE(parseToneCurve("filmic").has_value());
}

TEST(TonemapTest, AcesKnownValues) {
    EXPECT_EQ(mapOne(0.0f, ToneCurve::Aces), 0.0f);
    // (x (2.51 x + 0.03)) / (x (2.43 x + 0.59) + 0.14) at x = 1 and 0.18.
    EXPECT_NEAR(mapOne(1.0f, ToneCurve::Aces), 2.54 / 3.16, 1e-6);
    EXPECT_NEAR(mapOne(0.18f, ToneCurve::Aces), 0.086724 / 0.324932, 1e-5);
    EXPECT_EQ(mapOne(100.0f, ToneCurve::Aces), 1.0f);
}

TEST(TonemapTest, CurvesAreMonotonicAndStayInRange) {
    for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::Reinhard, ToneCurve::Aces}) {
        float previous = 0.0f;
        for (int i = 0; i <= 4000; ++i) {
            const float x = static_cast<float>(i) * 0.005f;
            const float y = mapOne(x, curve);
            EXPECT_GE(y, previous) << x;
            EXPECT_LE(y, 1.0f);
            previous = y;
        }
    }
}

TEST(TonemapTest, ReinhardAndClampKnownValues) {
    EXPECT_FLOAT_EQ(mapOne(1.0f, ToneCurve::Reinhard), 0.5f);
    EXPECT_FLOAT_EQ(mapOne(3.0f, ToneCurve::Reinhard), 0.75f);
    EXPECT_FLOAT_EQ(mapOne(0.25f, ToneCurve::Clamp), 0.25f);
    EXPECT_EQ(mapOne(7.0f, ToneCurve::Clamp), 1.0f);
    EXPECT_EQ(mapOne(-1.0f, ToneCurve::Reinhard), 0.0f);
}

TEST(TonemapTest, ExposureOneStopDoublesTheInput) {
    for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::Reinhard, ToneCurve::Aces}) {
        for (float x : {0.01f, 0.1f, 0.3f, 2.0f}) {
            EXPECT_FLOAT_EQ(mapOne(x, curve, 1.0f), mapOne(2.0f * x, curve));
            EXPECT_FLOAT_EQ(mapOne(x, curve, -2.0f), mapOne(0.25f * x, curve));
        }
    }
}

TEST(TonemapTest, NanAndInfinity) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::Reinhard, ToneCurve::Aces}) {
        EXPECT_EQ(mapOne(nan, curve), 0.0f);
        EXPECT_EQ(mapOne(inf, curve), 1.0f);
        EXPECT_EQ(mapOne(-inf, curve), 0.0f);
    }
}

TEST(TonemapTest, AlphaIsCopiedAndColourChannelsMapped) {
    Image rgba(2, 1, 4);
    rgba.setRgb(0, 0, Rgb(1.0f, 3.0f, 0.0f));
    rgba.at(0, 0, 3) = 0.25f;
    rgba.at(1, 0, 3) = 7.0f;
    const Image out = toneMap(rgba, {0.0f, ToneCurve::Reinhard});
    ASSERT_EQ(out.channels(), 4);
    EXPECT_EQ(out.rgb(0, 0), Rgb(0.5f, 0.75f, 0.0f));
    EXPECT_EQ(out.at(0, 0, 3), 0.25f);
    EXPECT_EQ(out.at(1, 0, 3), 7.0f);

    Image greyAlpha(1, 1, 2);
    greyAlpha.at(0, 0, 0) = 1.0f;
    greyAlpha.at(0, 0, 1) = 3.0f;
    const Image ga = toneMap(greyAlpha, {0.0f, ToneCurve::Reinhard});
    EXPECT_EQ(ga.at(0, 0, 0), 0.5f);
    EXPECT_EQ(ga.at(0, 0, 1), 3.0f);
}

}  // namespace
}  // namespace luxel
