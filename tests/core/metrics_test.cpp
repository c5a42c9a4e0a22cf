// Tests for image comparison metrics against hand-computed values.
#include "luxel/core/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace luxel {
namespace {

Image fromValues(int width, int height, int channels, std::initializer_list<float> values) {
    Image image(width, height, channels);
    int i = 0;
    for (float v : values) image.data()[i++] = v;
    return image;
}

TEST(MetricsTest, IdenticalImagesHaveZeroError) {
    const Image a = fromValues(2, 1, 3, {1, 2, 3, 4, 5, 6});
    const Result<ImageErrors> errors = compareImages(a, a);
    ASSERT_TRUE(errors.ok());
    EXPECT_EQ(errors->rmse, 0.0);
    EXPECT_EQ(errors->relativeL1, 0.0);
    EXPECT_EQ(errors->maxAbsError, 0.0);
    EXPECT_DOUBLE_EQ(errors->meanReference, 3.5);
    EXPECT_EQ(errors->countedPixels, 2u);
}

TEST(MetricsTest, HandComputedValues) {
    // Differences 1, -2, 0, 3: squares 1 + 4 + 0 + 9 = 14; |diff| sum 6; |b| sum 10.
    const Image a = fromValues(2, 2, 1, {2, 0, 3, 7});
    const Image b = fromValues(2, 2, 1, {1, 2, 3, 4});
    const Result<ImageErrors> errors = compareImages(a, b);
    ASSERT_TRUE(errors.ok()) << errors.error().message();
    EXPECT_DOUBLE_EQ(errors->rmse, std::sqrt(14.0 / 4.0));
    EXPECT_DOUBLE_EQ(errors->relativeL1, 6.0 / 10.0);
    EXPECT_DOUBLE_EQ(errors->maxAbsError, 3.0);
    EXPECT_DOUBLE_EQ(errors->meanReference, 2.5);
    EXPECT_EQ(errors->countedPixels, 4u);
}

TEST(MetricsTest, AllChannelsCount) {
    // One pixel, three channels: differences 0.5, 0, -1.5.
    const Image a = fromValues(1, 1, 3, {1.5f, 2.0f, 1.5f});
    const Image b = fromValues(1, 1, 3, {1.0f, 2.0f, 3.0f});
    const Result<ImageErrors> errors = compareImages(a, b);
    ASSERT_TRUE(errors.ok());
    EXPECT_DOUBLE_EQ(errors->rmse, std::sqrt((0.25 + 2.25) / 3.0));
    EXPECT_DOUBLE_EQ(errors->relativeL1, 2.0 / 6.0);
    EXPECT_DOUBLE_EQ(errors->maxAbsError, 1.5);
    EXPECT_EQ(errors->countedPixels, 1u);
}

TEST(MetricsTest, MaskExcludesPixels) {
    const Image a = fromValues(3, 1, 1, {2, 100, 5});
    const Image b = fromValues(3, 1, 1, {1, 0, 4});
    const Image mask = fromValues(3, 1, 1, {1.0f, 0.5f, 0.75f});  // 0.5 is not > 0.5
    const Result<ImageErrors> errors = compareImages(a, b, &mask);
    ASSERT_TRUE(errors.ok()) << errors.error().message();
    EXPECT_EQ(errors->countedPixels, 2u);
    EXPECT_DOUBLE_EQ(errors->rmse, 1.0);
    EXPECT_DOUBLE_EQ(errors->relativeL1, 2.0 / 5.0);
    EXPECT_DOUBLE_EQ(errors->maxAbsError, 1.0);
    EXPECT_DOUBLE_EQ(errors->meanReference, 2.5);
}

TEST(MetricsTest, ZeroReference) {
    const Image zero(2, 2, 1);
    const Result<ImageErrors> both = compareImages(zero, zero);
    ASSERT_TRUE(both.ok());
    EXPECT_EQ(both->relativeL1, 0.0);

    const Image a = fromValues(2, 2, 1, {0, 0, 0, 1});
    const Result<ImageErrors> onlyReference = compareImages(a, zero);
    ASSERT_TRUE(onlyReference.ok());
    EXPECT_EQ(onlyReference->relativeL1, std::numeric_limits<double>::infinity());
    EXPECT_DOUBLE_EQ(onlyReference->rmse, 0.5);
}

TEST(MetricsTest, AccumulatesInDouble) {
    // A float running sum of a million 0.2s drifts by far more than 1e-9.
    Image a(1024, 1024, 1), b(1024, 1024, 1);
    a.fill(0.1f);
    b.fill(0.2f);
    const Result<ImageErrors> errors = compareImages(a, b);
    ASSERT_TRUE(errors.ok());
    const double diff = static_cast<double>(0.2f) - static_cast<double>(0.1f);
    EXPECT_NEAR(errors->relativeL1, diff / static_cast<double>(0.2f), 1e-12);
    EXPECT_NEAR(errors->rmse, diff, 1e-12);
    EXPECT_NEAR(errors->meanReference, static_cast<double>(0.2f), 1e-12);
}

TEST(MetricsTest, MismatchedSizesAreAnError) {
    const Image a(4, 3, 3), b(4, 4, 3), c(4, 3, 1);
    const Result<ImageErrors> sizes = compareImages(a, b);
    ASSERT_FALSE(sizes.ok());
    const std::string message = sizes.error().message();
    EXPECT_NE(message.find("4x3"), std::string::npos) << message;
    EXPECT_NE(message.find("4x4"), std::string::npos) << message;

    const Result<ImageErrors> channels = compareImages(a, c);
    ASSERT_FALSE(channels.ok());
    EXPECT_NE(channels.error().message().find("3 channels"), std::string::npos);

    const Image wrongMask(4, 4, 1), rgbMask(4, 3, 3);
    const Result<ImageErrors> masked = compareImages(a, a, &wrongMask);
    ASSERT_FALSE(masked.ok());
    EXPECT_NE(masked.error().message().find("4x4"), std::string::npos);
    EXPECT_NE(masked.error().message().find("4x3"), std::string::npos);
    EXPECT_FALSE(compareImages(a, a, &rgbMask).ok());
}

}  // namespace
}  // namespace luxel
