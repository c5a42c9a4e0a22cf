// The viewer's adaptive internal resolution against a simulated renderer whose frame time is
// proportional to the pixel count.
#include <gtest/gtest.h>

#include <cmath>

#include "adaptive_resolution.h"

namespace luxel::viewer {
namespace {

// Feeds frames of `msPerMegapixel` cost until the size settles; returns the final size.
ImageSize settle(AdaptiveResolution& adaptive, double msPerMegapixel, int frames = 40,
                 int* changes = nullptr) {
    double t = 0.0;
    for (int i = 0; i < frames; ++i) {
        const ImageSize s = adaptive.current();
        const double ms = msPerMegapixel * s.width * s.height / 1e6;
        t += ms / 1000.0;
        if (adaptive.frameRendered(s, ms, t) && changes) ++*changes;
    }
    return adaptive.current();
}

double frameMs(ImageSize s, double msPerMegapixel) {
    return msPerMegapixel * s.width * s.height / 1e6;
}

TEST(AdaptiveResolution, GrowsToTheLargestSizeThatMeetsTheTarget) {
    AdaptiveResolution adaptive({128, 72}, 50.0);
    adaptive.setLargest({1280, 720});
    // 200 ms per megapixel: 50 ms allows 0.25 Mpx, e.g. about 667x375.
    const ImageSize s = settle(adaptive, 200.0);
    EXPECT_LE(frameMs(s, 200.0), 50.0);
    EXPECT_GE(frameMs(s, 200.0), 0.5 * 50.0) << s.width << "x" << s.height;
    EXPECT_NEAR(static_cast<double>(s.width) / s.height, 1280.0 / 720.0, 0.02);
}

TEST(AdaptiveResolution, StopsAtTheWindowWhenRenderingIsCheap) {
    AdaptiveResolution adaptive({128, 128}, 50.0);
    adaptive.setLargest({512, 512});
    EXPECT_EQ(settle(adaptive, 1.0), (ImageSize{512, 512}));
}

TEST(AdaptiveResolution, ShrinksOnlyAfterTwoSlowFrames) {
    AdaptiveResolution adaptive({640, 360}, 50.0);
    adaptive.setLargest({1280, 720});
    // One slow frame (a first frame paying for allocation) changes nothing.
    EXPECT_FALSE(adaptive.frameRendered({640, 360}, 400.0, 0.4));
    EXPECT_FALSE(adaptive.frameRendered({640, 360}, 30.0, 0.5));
    EXPECT_FALSE(adaptive.frameRendered({640, 360}, 400.0, 0.9));
    const auto next = adaptive.frameRendered({640, 360}, 400.0, 1.3);
    ASSERT_TRUE(next);
    EXPECT_LT(next->width, 640);
    EXPECT_GE(next->width, 320);  // at most a factor 2 per change
}

TEST(AdaptiveResolution, SettlesWithoutOscillating) {
    AdaptiveResolution adaptive({160, 90}, 66.0);
    adaptive.setLargest({1920, 1080});
    int changes = 0;
    settle(adaptive, 300.0, 20, &changes);
    const int settledAfter = changes;
    settle(adaptive, 300.0, 200, &changes);
    EXPECT_EQ(changes, settledAfter);
    EXPECT_LE(settledAfter, 4);
}

TEST(AdaptiveResolution, FollowsAWindowThatShrinks) {
    AdaptiveResolution adaptive({512, 512}, 50.0);
    adaptive.setLargest({512, 512});
    adaptive.setLargest({256, 256});
    const auto next = adaptive.frameRendered({512, 512}, 10.0, 0.1);
    ASSERT_TRUE(next);
    EXPECT_EQ(*next, (ImageSize{256, 256}));
}

TEST(AdaptiveResolution, IgnoresFramesOfAnotherSizeAndBadTimes) {
    AdaptiveResolution adaptive({128, 128}, 50.0);
    adaptive.setLargest({1024, 1024});
    EXPECT_FALSE(adaptive.frameRendered({64, 64}, 1.0, 0.1));  // a frame from before a change
    EXPECT_FALSE(adaptive.frameRendered({128, 128}, std::nan(""), 0.2));
    EXPECT_FALSE(adaptive.frameRendered({128, 128}, 0.0, 0.3));
    EXPECT_EQ(adaptive.current(), (ImageSize{128, 128}));
}

TEST(AdaptiveResolution, NeverBelowTheSmallestSide) {
    AdaptiveResolution adaptive({64, 64}, 10.0);
    adaptive.setLargest({640, 640});
    const ImageSize s = settle(adaptive, 1e6);  // hopelessly slow
    EXPECT_GE(std::min(s.width, s.height), AdaptiveResolution::kSmallestSide);
}

}  // namespace
}  // namespace luxel::viewer
