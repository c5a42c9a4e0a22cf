// luxel-view's first look under a virtual X display: without a size given, the internal
// resolution grows from its cheap start to what the machine renders at the target frame rate.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "luxel/core/image.h"
#include "viewer_xvfb.h"

namespace {

using luxel::Image;
using luxel::test::RunResult;
using luxel::test::ViewerXvfb;

// A 256x256 canvas with one lamp: HRC renders it at full size in a few milliseconds.
const char* kLampScene = R"({
  "canvas": [256, 256],
  "background": {"emission": 0, "absorption": 0.0005},
  "shapes": [
    {"type": "circle", "name": "lamp", "center": [96, 128], "radius": 10,
     "emission": [1.0, 0.9, 0.8], "intensity": 6, "opaque": true}
  ]
})";

// "2D mode, 256x256 internal" in the exit summary -> 256.
int summaryInternalWidth(const std::string& output) {
    const auto at = output.find(" internal,");
    if (at == std::string::npos) return 0;
    const auto start = output.rfind(", ", at);
    int w = 0, h = 0;
    if (std::sscanf(output.c_str() + start + 2, "%dx%d", &w, &h) != 2) return 0;
    return w;
}

TEST_F(ViewerXvfb, TheInternalSizeGrowsToTheWindowWhenFramesAreFast) {
    const std::string scene = write("lamp.json", kLampScene);
    write("look.txt",
          "wait_render\n"
          "wait_frames 10\n"
          "wait_render\n"
          "wait_frames 10\n"
          "wait_render\n"
          "screenshot shot.png\n"
          "quit\n");
    // The CPU starts at 128 px on the long side. A target of 4 s a frame leaves room for the full
    // 256x256 window on any machine that runs the tests, even a loaded one: any first frame under
    // 800 ms doubles the side at once (adaptive_resolution.h), and these take 5-300 ms.
    const RunResult r =
        view(scene + " --size 256x256 --backend cpu --target-fps 0.25 --script look.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(summaryInternalWidth(r.output), 256) << r.output;
    EXPECT_EQ(png("shot.png").width(), 256);
}

TEST_F(ViewerXvfb, AFixedTargetOfZeroKeepsTheStartingSize) {
    const std::string scene = write("lamp.json", kLampScene);
    write("look.txt", "wait_render\nwait_frames 10\nwait_render\nscreenshot shot.png\nquit\n");
    const RunResult r =
        view(scene + " --size 256x256 --backend cpu --target-fps 0 --script look.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(summaryInternalWidth(r.output), 128) << r.output;
    EXPECT_EQ(png("shot.png").width(), 128);
}

}  // namespace
