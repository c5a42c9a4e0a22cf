// PSNR and SSIM against values known in closed form.
#include "luxel/core/image_quality.h"

#include <gtest/gtest.h>

#include <cmath>

#include "post/post_test_images.h"

namespace luxel {
namespace {

Image texture(int w, int h) {
    Image image(w, h, 3);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float v = 0.5f + 0.4f * std::sin(x * 0.7f) * std::cos(y * 0.3f);
            image.setRgb(x, y, Rgb(v, 1.0f - v, 0.25f + 0.5f * v * v));
        }
    }
    return image;
}

TEST(ImageQuality, IdenticalImagesHaveInfinitePsnrAndUnitSsim) {
    const Image a = texture(40, 30);
    EXPECT_TRUE(std::isinf(psnr(a, a).value()));
    EXPECT_NEAR(ssim(a, a).value(), 1.0, 1e-12);
}

TEST(ImageQuality, PsnrOfAKnownNoiseLevel) {
    // +-d on alternate pixels: MSE = d^2 exactly, PSNR = -20 log10(d).
    const Image a = texture(32, 32);
    Image b = a;
    const float d = 0.01f;
    for (std::size_t i = 0; i < b.size(); ++i) b.data()[i] += (i / 3) % 2 ? d : -d;
    EXPECT_NEAR(psnr(b, a).value(), -20.0 * std::log10(double(d)), 1e-3);
    EXPECT_NEAR(psnr(b, a, 255.0).value(), 20.0 * std::log10(255.0 / d), 1e-3);
}

TEST(ImageQuality, SsimOfFlatImagesIsTheLuminanceTerm) {
    // No variance: the contrast-structure term is c2 / c2 = 1, leaving
    // (2 mu_a mu_b + c1) / (mu_a^2 + mu_b^2 + c1).
    Image a(20, 20, 3), b(20, 20, 3);
    a.fill(0.2f);
    b.fill(0.6f);
    const double c1 = 1e-4, mu = 0.2, nu = 0.6;
    EXPECT_NEAR(ssim(a, b).value(), (2 * mu * nu + c1) / (mu * mu + nu * nu + c1), 1e-6);
}

TEST(ImageQuality, SsimFallsWithNoiseAndRejectsMismatchedSizes) {
    const Image a = texture(48, 48);
    Image slight = a, heavy = a;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const float s = (i * 2654435761u) % 1000 / 1000.0f - 0.5f;
        slight.data()[i] += 0.02f * s;
        heavy.data()[i] += 0.4f * s;
    }
    const double hi = ssim(slight, a).value(), lo = ssim(heavy, a).value();
    EXPECT_LT(hi, 1.0);
    EXPECT_LT(lo, hi);
    EXPECT_GT(hi, 0.8);
    EXPECT_FALSE(ssim(a, texture(48, 47)));
    EXPECT_FALSE(psnr(a, Image(48, 48, 1)));
}

}  // namespace
}  // namespace luxel
