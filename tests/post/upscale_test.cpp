// Upscalers: constants, ranges and quality on an analytic edge against the bilinear baseline.
#include "luxel/post/upscale.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "luxel/core/image_quality.h"
#include "post/post_test_images.h"

namespace luxel::post {
namespace {

// A disk of radius r (in units of the image height) at the centre, white on dark grey, each pixel
// its exact coverage estimated with 8 x 8 samples: the ground truth at any resolution.
Image disk(int w, int h) {
    Image image(w, h, 3);
    const double r = 0.3 * h, cx = 0.5 * w, cy = 0.5 * h;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int inside = 0;
            for (int j = 0; j < 8; ++j) {
                for (int i = 0; i < 8; ++i) {
                    const double dx = x + (i + 0.5) / 8 - cx, dy = y + (j + 0.5) / 8 - cy;
                    inside += dx * dx + dy * dy < r * r;
                }
            }
            const float v = 0.1f + 0.8f * inside / 64.0f;
            image.setRgb(x, y, Rgb(v, v, v));
        }
    }
    return image;
}

TEST(PostUpscale, InternalSideRoundsAndStaysPositive) {
    EXPECT_EQ(internalSide(960, 0.5f), 480);
    EXPECT_EQ(internalSide(541, 0.5f), 271);
    EXPECT_EQ(internalSide(1, 0.25f), 1);
}

TEST(PostUpscale, ConstantsStayConstant) {
    Image flat(13, 9, 3);
    flat.fill(0.75f);
    for (Upscaler u : {Upscaler::Bilinear, Upscaler::Edge}) {
        const Image out = upscale(flat, 26, 18, u);
        ASSERT_EQ(out.width(), 26);
        for (std::size_t i = 0; i < out.size(); ++i) ASSERT_NEAR(out.data()[i], 0.75f, 1e-6f);
    }
}

TEST(PostUpscale, EdgeAwareStaysWithinTheSourceRange) {
    const Image src = test::randomHdr(24, 16, 3);
    float lo = src.data()[0], hi = lo;
    for (std::size_t i = 0; i < src.size(); ++i) {
        lo = std::min(lo, src.data()[i]);
        hi = std::max(hi, src.data()[i]);
    }
    const Image out = upscaleEdge(src, 48, 32);
    for (std::size_t i = 0; i < out.size(); ++i) {
        ASSERT_GE(out.data()[i], lo);
        ASSERT_LE(out.data()[i], hi);
    }
}

TEST(PostUpscale, EdgeAwareBeatsBilinearOnAnAnalyticEdge) {
    const Image truth = disk(128, 96);
    const Image low = disk(64, 48);
    const double bilinear = psnr(upscaleBilinear(low, 128, 96), truth).value();
    const double edge = psnr(upscaleEdge(low, 128, 96), truth).value();
    const double bilinearSsim = ssim(upscaleBilinear(low, 128, 96), truth).value();
    const double edgeSsim = ssim(upscaleEdge(low, 128, 96), truth).value();
    EXPECT_GT(edge, bilinear + 0.5) << "bilinear " << bilinear << " dB, edge " << edge << " dB";
    EXPECT_GT(edgeSsim, bilinearSsim);
}

TEST(PostUpscale, SharpeningIsLimitedToTheNeighbourhood) {
    const Image low = disk(32, 24);
    const Image soft = upscaleBilinear(low, 64, 48);
    EXPECT_EQ(sharpen(soft, 0.0f), soft);
    const Image sharp = sharpen(soft, 1.0f);
    const Image truth = disk(64, 48);
    EXPECT_GT(psnr(sharp, truth).value(), psnr(soft, truth).value());
    for (int y = 1; y < 47; ++y) {
        for (int x = 1; x < 63; ++x) {
            float lo = soft.at(x, y, 0), hi = lo;
            for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                lo = std::min(lo, soft.at(x + dx, y + dy, 0));
                hi = std::max(hi, soft.at(x + dx, y + dy, 0));
            }
            ASSERT_GE(sharp.at(x, y, 0), lo - 1e-6f);
            ASSERT_LE(sharp.at(x, y, 0), hi + 1e-6f);
        }
    }
}

}  // namespace
}  // namespace luxel::post
