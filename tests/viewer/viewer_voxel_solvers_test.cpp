// luxel-view's voxel solvers end to end under a virtual X display: the progressive path tracer
// (samples grow while the view is still, start over when it moves, and the mean at the target is
// `luxel render --solver path --spp N`'s picture), sky visibility (`luxel render --solver ao`'s
// picture) and the C key. Screenshots carry the solver and the samples in their metadata.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "luxel/core/image_io.h"
#include "viewer_xvfb.h"

namespace {

using luxel::Image;
using luxel::ImageMetadata;
using luxel::test::meanAbsDiff;
using luxel::test::run;
using luxel::test::RunResult;
using luxel::test::ViewerXvfb;

// Small terrain seen at 64x36, so path tracing converges in a moment. Yaw and pitch (rather than
// a look_at point) give the viewer's fly camera the scene camera's rays.
const char* kTerrain = R"({
  "type": "voxel",
  "world": {"source": "terrain", "size": [48, 24, 48], "seed": 5, "height": 0.35,
            "amplitude": 0.3, "frequency": 0.04, "water": 0.2},
  "camera": {"position": [24, 22, 2], "yaw": 0, "pitch": -25, "fov": 60, "size": [64, 36]},
  "sun": [0.4, 1.0, 0.3]
})";

const std::string kWindow = " --size 256x144 --internal-size 64x36 --target-fps 0";

class ViewerVoxelSolvers : public ViewerXvfb {
  protected:
    // A screenshot's metadata entry (empty when missing).
    std::string meta(const std::string& name, const char* key) {
        ImageMetadata metadata;
        auto image = luxel::readPng(path(name), luxel::PngEncoding::Srgb, &metadata);
        EXPECT_TRUE(image) << (image ? "" : image.error().message());
        const std::string* value = luxel::findMetadata(metadata, key);
        return value ? *value : std::string();
    }
    int samples(const std::string& name) {
        const std::string text = meta(name, "luxel.samples");
        EXPECT_FALSE(text.empty()) << name << " has no luxel.samples";
        return text.empty() ? -1 : std::atoi(text.c_str());
    }
    RunResult cli(const std::string& args) {
        return run("cd '" + dir().string() + "' && " + LUXEL_CLI_PATH + " render " + args);
    }
};

// Largest per-channel difference of two 8-bit pictures, in 1/255 steps, and how many values
// differ at all.
struct PictureDifference {
    int largest = 0;
    std::size_t differing = 0;
};

PictureDifference difference(const Image& a, const Image& b) {
    PictureDifference d;
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    if (a.size() != b.size()) return {255, a.size()};
    for (std::size_t i = 0; i < a.size(); ++i) {
        const int steps = static_cast<int>(std::lround(std::fabs(a.data()[i] - b.data()[i]) * 255));
        d.largest = std::max(d.largest, steps);
        d.differing += steps > 0;
    }
    return d;
}

TEST_F(ViewerVoxelSolvers, PathSamplesGrowWhileStillAndStartOverWhenTheCameraMoves) {
    const std::string scene = write("terrain.json", kTerrain);
    write("path.txt",
          "wait_render\n"
          "wait 0.4\n"
          "screenshot early.png\n"
          "wait 1.2\n"
          "screenshot later.png\n"
          "key W\n"
          "wait_render\n"
          "screenshot moved.png\n"
          "quit\n");
    const RunResult r = view(scene + kWindow + " --solver path --spp 100000 --script path.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(meta("early.png", "luxel.solver"), "path");
    const int early = samples("early.png"), later = samples("later.png");
    const int moved = samples("moved.png");
    std::printf("samples per pixel: %d after 0.4 s, %d after 1.6 s, %d after the move\n", early,
                later, moved);
    EXPECT_GE(early, 1);
    EXPECT_GT(later, early);
    EXPECT_GE(moved, 1);
    EXPECT_LT(moved, later);  // the move threw the samples away
    EXPECT_GT(meanAbsDiff(png("later.png"), png("moved.png")), 0.01);  // and shows another view
    EXPECT_EQ(meta("later.png", "luxel.path.target"), "100000");
    EXPECT_FALSE(meta("later.png", "luxel.path.relative_error").empty());
}

TEST_F(ViewerVoxelSolvers, PathAtItsTargetIsLuxelRenderOfThatManySamples) {
    const std::string scene = write("terrain.json", kTerrain);
    write("converge.txt", "wait_converged\nscreenshot view.png\nquit\n");
    const RunResult r = view(scene + kWindow + " --solver path --spp 12 --script converge.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(samples("view.png"), 12);
    const RunResult c = cli(scene + " --solver path --spp 12 --png cli.png");
    ASSERT_EQ(c.exitCode, 0) << c.output;
    const Image view = png("view.png"), cli = png("cli.png");
    const PictureDifference d = difference(view, cli);
    std::printf("viewer vs luxel render, 12 spp: %zu of %zu values differ, largest by %d/255\n",
                d.differing, view.size(), d.largest);
    EXPECT_EQ(d.differing, 0u);
}

TEST_F(ViewerVoxelSolvers, SkyVisibilityIsLuxelRenderAndCCyclesTheSolvers) {
    const std::string scene = write("terrain.json", kTerrain);
    write("cycle.txt",
          "wait_render\n"
          "screenshot ao.png\n"
          "key C\n"
          "wait_render\n"
          "screenshot path.png\n"
          "key C\n"
          "wait_render\n"
          "screenshot rc.png\n"
          "key C\n"
          "wait_render\n"
          "screenshot raycast.png\n"
          "quit\n");
    const std::string ao = " --solver ao --ao-rays 8 --ao-radius 10";
    const RunResult r = view(scene + kWindow + ao + " --script cycle.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(meta("ao.png", "luxel.solver"), "ao");
    EXPECT_EQ(meta("ao.png", "luxel.ao.rays"), "8");
    EXPECT_EQ(meta("path.png", "luxel.solver"), "path");
    EXPECT_EQ(meta("rc.png", "luxel.solver"), "rc");
    EXPECT_EQ(meta("raycast.png", "luxel.solver"), "raycast");
    const RunResult c = cli(scene + ao + " --png cli.png");
    ASSERT_EQ(c.exitCode, 0) << c.output;
    const PictureDifference d = difference(png("ao.png"), png("cli.png"));
    std::printf("viewer vs luxel render, sky visibility: %zu values differ, largest by %d/255\n",
                d.differing, d.largest);
    EXPECT_EQ(d.differing, 0u);
    EXPECT_GT(meanAbsDiff(png("ao.png"), png("raycast.png")), 0.005);  // another solver
}

TEST_F(ViewerVoxelSolvers, SolversOfTheOtherKindOfSceneAreOneClearLine) {
    const std::string voxel = write("terrain.json", kTerrain);
    RunResult r = view(voxel + " --solver hrc");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel-view: error: --solver hrc is a 2D solver; voxel scenes take "
                            "raycast, ao, path or rc"),
              std::string::npos)
        << r.output;
    const std::string room = write("room.json", R"({"canvas": [32, 32], "shapes": []})");
    r = view(room + " --solver path");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel-view: error: --solver path applies to voxel scenes"),
              std::string::npos)
        << r.output;
    r = view(room + " --spp 4");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel-view: error: --spp applies to voxel scenes"), std::string::npos)
        << r.output;
}

}  // namespace
