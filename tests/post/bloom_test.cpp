// Dual-filter bloom: energy, constants, symmetry and level clamping.
#include "luxel/post/bloom.h"

#include <gtest/gtest.h>

#include <cmath>

#include "post/post_test_images.h"

namespace luxel::post {
namespace {

TEST(PostBloom, KeepsMeanRadianceOfRandomHdrImages) {
    // Power-of-two sizes: every filter tiles the image, so only the clamped borders move energy.
    for (int size : {64, 128}) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const Image in = test::randomHdr(size, size, seed);
            const Image out = bloom(in, {1.0f, 5, false});
            const double before = test::meanOf(in), after = test::meanOf(out);
            EXPECT_NEAR(after / before, 1.0, 0.01) << size << " seed " << seed;
        }
    }
    // Odd sizes resample between texel grids; the stated tolerance is 2 %.
    const Image odd = test::randomHdr(77, 53, 9);
    EXPECT_NEAR(test::meanOf(bloom(odd, {1.0f, 4, false})) / test::meanOf(odd), 1.0, 0.02);
}

TEST(PostBloom, EachPassKeepsTheMeanOfASmoothImage) {
    // A smooth ramp has equal borders on opposite sides, so the clamp's gains and losses cancel.
    Image ramp(64, 64, 3);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) ramp.setRgb(x, y, Rgb(1.0f + x * 0.01f, 2.0f, 0.5f));
    }
    const Image down = bloomDownsample(ramp, false);
    EXPECT_EQ(down.width(), 32);
    EXPECT_NEAR(test::meanOf(down), test::meanOf(ramp), 1e-5);
    const Image up = bloomUpsampleAdd(down, ramp, 0.0f, 1.0f);
    EXPECT_NEAR(test::meanOf(up), test::meanOf(ramp), 1e-5);
}

TEST(PostBloom, LeavesAConstantImageUnchanged) {
    for (auto [w, h] : {std::pair{64, 64}, std::pair{37, 21}, std::pair{5, 300}}) {
        Image in(w, h, 3);
        in.fill(2.5f);
        const Image out = bloom(in, {0.8f, 6, false});
        for (std::size_t i = 0; i < out.size(); ++i) {
            ASSERT_NEAR(out.data()[i], 2.5f, 1e-5f) << w << "x" << h << " at " << i;
        }
    }
}

TEST(PostBloom, SpreadsASingleBrightPixelSymmetrically) {
    // A 2 x 2 pixel at the centre of a 64 x 64 image: its centre is a texel corner of every level.
    const int n = 64, c = 32;
    Image in(n, n, 3);
    for (int y = c - 1; y <= c; ++y) {
        for (int x = c - 1; x <= c; ++x) in.setRgb(x, y, Rgb(1000.0f, 1000.0f, 1000.0f));
    }
    const Image out = bloom(in, {0.5f, 5, false});
    const float peak = out.at(c, c, 0);
    EXPECT_FLOAT_EQ(out.at(c - 1, c - 1, 0), peak);
    EXPECT_LT(peak, 1000.0f);
    EXPECT_GT(peak, 500.0f);  // (1 - strength) of it stays in place
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const float v = out.at(x, y, 1);
            ASSERT_NEAR(v, out.at(n - 1 - x, y, 1), 1e-4f * peak) << x << "," << y;
            ASSERT_NEAR(v, out.at(x, n - 1 - y, 1), 1e-4f * peak) << x << "," << y;
            ASSERT_NEAR(v, out.at(y, x, 1), 1e-4f * peak) << x << "," << y;
        }
    }
    // It spreads, falling off with distance.
    for (int d = 1; d < 20; ++d) {
        EXPECT_GT(out.at(c + d, c, 0), 0.0f) << d;
        if (d > 1) {
            EXPECT_LT(out.at(c + d, c, 0), out.at(c + d - 1, c, 0)) << d;
        }
    }
    // The widest levels reach the borders, where clamping loses a little (0.24 % here).
    EXPECT_NEAR(test::meanOf(out), test::meanOf(in), 0.005 * test::meanOf(in));
}

TEST(PostBloom, ClampsTheLevelCountForTinyImages) {
    EXPECT_EQ(bloomLevels(1, 1, 5), 0);
    EXPECT_EQ(bloomLevels(2, 2, 5), 0);
    EXPECT_EQ(bloomLevels(3, 3, 5), 1);
    EXPECT_EQ(bloomLevels(4, 100, 5), 1);
    EXPECT_EQ(bloomLevels(1024, 1024, 5), 5);
    EXPECT_EQ(bloomLevels(1024, 768, 20), 9);
    Image one(1, 1, 3);
    one.fill(7.0f);
    EXPECT_EQ(bloom(one, {1.0f, 5, false}), one);
    const Image small = test::randomHdr(3, 2, 4);
    const Image out = bloom(small, {1.0f, 5, false});
    EXPECT_EQ(out.width(), 3);
    EXPECT_EQ(out.height(), 2);
}

TEST(PostBloom, ZeroStrengthIsTheIdentityAndKarisTamesFireflies) {
    const Image in = test::randomHdr(32, 32, 5);
    EXPECT_EQ(bloom(in, {0.0f, 5, false}), in);
    Image firefly(32, 32, 3);
    firefly.fill(1.0f);
    firefly.setRgb(16, 16, Rgb(1e5f, 1e5f, 1e5f));
    const float plain = bloom(firefly, {1.0f, 4, false}).at(8, 8, 0);
    const float karis = bloom(firefly, {1.0f, 4, true}).at(8, 8, 0);
    EXPECT_LT(karis, plain);
    EXPECT_LT(karis, 2.0f);
}

}  // namespace
}  // namespace luxel::post
