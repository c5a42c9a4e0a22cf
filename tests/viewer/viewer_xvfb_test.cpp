// luxel-view end to end under a virtual X display (Debian xvfb): scripted input, screenshots, and
// what the pictures must show. xvfb-run is a listed dependency, so its absence fails loudly.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/gi2d/scene2d_json.h"
#include "luxel/gpu/context.h"
#include "viewer_xvfb.h"

namespace {

namespace fs = std::filesystem;
using luxel::Image;
using luxel::test::meanAbsDiff;
using luxel::test::regionMean;
using luxel::test::run;
using luxel::test::RunResult;
using luxel::test::stddev;
using luxel::test::ViewerXvfb;

// A 256x256 room: a lamp on the left and an opaque pillar in the middle.
const char* kLampScene = R"({
  "canvas": [256, 256],
  "background": {"emission": 0, "absorption": 0.0005},
  "shapes": [
    {"type": "box", "name": "pillar", "center": [128, 200], "size": [16, 60], "opaque": true},
    {"type": "circle", "name": "lamp", "center": [64, 96], "radius": 12,
     "emission": [1.0, 0.9, 0.8], "intensity": 6, "opaque": true}
  ]
})";

const char* kVoxelScene = R"({
  "type": "voxel",
  "world": {"source": "terrain", "size": [64, 32, 64], "seed": 3, "height": 0.35,
            "amplitude": 0.3, "frequency": 0.03, "water": 0.25},
  "camera": {"position": [32, 34, 2], "look_at": [32, 10, 40], "fov": 60, "size": [320, 180]},
  "sun": [0.4, 1.0, 0.3],
  "render": {"reflections": 1, "shadows": true, "textures": true}
})";

TEST_F(ViewerXvfb, DraggingTheLightMovesTheLightAndRTogglesGi) {
    const std::string scene = write("lamp.json", kLampScene);
    write("drag.txt",
          "wait_render\n"
          "screenshot before.png\n"
          "mouse_down 64 96\n"
          "mouse_move 100 96\n"
          "wait_frames 2\n"
          "mouse_move 150 96\n"
          "mouse_up 192 96\n"
          "wait_render\n"
          "screenshot after.png\n"
          "key R\n"
          "wait_render\n"
          "screenshot nogi.png\n"
          "key R\n"
          "key Space\n"
          "wait_render\n"
          "screenshot probes.png\n"
          "screenshot_window window.png\n"
          "resize 384 256\n"
          "wait_frames 3\n"
          "screenshot_window resized.png\n"
          "quit\n");
    const RunResult r = view(scene +
                             " --size 256x256 --internal-scale 1 --backend cpu --record 3 "
                             "--record-dir rec --script drag.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Image before = png("before.png"), after = png("after.png"), nogi = png("nogi.png");
    ASSERT_EQ(before.width(), 256);
    // Not blank: lit, with structure.
    EXPECT_GT(regionMean(before, 128, 128, 128), 0.05);
    EXPECT_GT(stddev(before), 0.05);
    // The light left (64, 96) and arrived at (192, 96); a region beside each position shows it.
    const double oldBefore = regionMean(before, 64, 96, 20),
                 oldAfter = regionMean(after, 64, 96, 20);
    const double newBefore = regionMean(before, 192, 96, 20),
                 newAfter = regionMean(after, 192, 96, 20);
    EXPECT_GT(newAfter, 2.0 * newBefore)
        << "near the new position: " << newBefore << " -> " << newAfter;
    EXPECT_LT(oldAfter, 0.5 * oldBefore)
        << "near the old position: " << oldBefore << " -> " << oldAfter;
    // GI off: only the lamp itself stays lit; the room around it goes dark.
    EXPECT_GT(meanAbsDiff(after, nogi), 0.02);
    EXPECT_LT(regionMean(nogi, 64, 200, 30), 0.2 * regionMean(after, 64, 200, 30));
    EXPECT_GT(regionMean(nogi, 192, 96, 6), 0.5);  // the lamp
    // --record 3 wrote the first three rendered frames, then stopped.
    EXPECT_TRUE(fs::exists(path("rec/frame_00002.png")));
    EXPECT_FALSE(fs::exists(path("rec/frame_00003.png")));
    EXPECT_EQ(png("rec/frame_00000.png").width(), 256);
    EXPECT_NE(r.output.find("recorded 3 frames"), std::string::npos) << r.output;
    // SPACE marks probe centres: a sparse set of pixels changes, the rest stays.
    const Image probes = png("probes.png");
    int marked = 0;
    for (int y = 0; y < probes.height(); ++y) {
        for (int x = 0; x < probes.width(); ++x) {
            if (std::fabs(probes.rgb(x, y).g - after.rgb(x, y).g) > 0.05f) ++marked;
        }
    }
    EXPECT_GT(marked, 100);
    EXPECT_LT(marked, static_cast<int>(probes.pixelCount() / 4));
    // The window capture has the frame and the panels; the window can be resized.
    const Image window = png("window.png");
    EXPECT_EQ(window.width(), 256);
    EXPECT_GT(stddev(window), 0.05);
    const Image resized = png("resized.png");
    EXPECT_EQ(resized.width(), 384);
    EXPECT_EQ(resized.height(), 256);
    // The 256x256 frame is centred: bars at the sides, the picture in the middle.
    EXPECT_LT(regionMean(resized, 20, 240, 10), 0.1);
    EXPECT_GT(regionMean(resized, 64 + 200, 240, 6), 0.1);  // the lit floor at scene (200, 240)
}

TEST_F(ViewerXvfb, PaintModeDrawsAWallAndSavesAJsonTheLoaderReads) {
    const std::string scene = write("lamp.json", kLampScene);
    write("paint.txt",
          "wait_render\n"
          "key P\n"
          "mouse_down 110 40\n"
          "mouse_move 110 90\n"
          "mouse_move 110 140\n"
          "mouse_up 110 160\n"
          "key Tab\n"  // wall -> emitter
          "click 220 230\n"
          "key ctrl+s\n"
          "wait_render\n"
          "screenshot painted.png\n"
          "quit\n");
    const RunResult r = view(
        scene +
        " --size 256x256 --internal-scale 1 --backend cpu --save painted.json --script paint.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("luxel-view: saved painted.json"), std::string::npos) << r.output;
    auto loaded = luxel::gi2d::loadScene2D(path("painted.json"));
    ASSERT_TRUE(loaded) << loaded.error().message();
    ASSERT_GT(loaded->shapes.size(), 3u);
    EXPECT_EQ(loaded->shapes.back().name.rfind("paint-emitter", 0), 0u)
        << loaded->shapes.back().name;
    EXPECT_EQ(loaded->shapes[2].name.rfind("paint-wall", 0), 0u) << loaded->shapes[2].name;
    const Image painted = png("painted.png");
    // The wall at x = 110 is dark and shadows the right side of the room from the lamp.
    EXPECT_LT(regionMean(painted, 110, 100, 2), 0.5 * regionMean(painted, 90, 100, 2));
    EXPECT_GT(regionMean(painted, 220, 230, 2), 0.5);  // the painted emitter glows
}

TEST_F(ViewerXvfb, VoxelModeRendersTerrainAndMovesAndEdits) {
    const std::string scene = write("terrain.json", kVoxelScene);
    write("fly.txt",
          "wait_render\n"
          "screenshot start.png\n"
          "key W\nkey W\nkey W\nkey W\n"
          "wait_render\n"
          "screenshot moved.png\n"
          "click 160 120\n"
          "wait_render\n"
          "screenshot edited.png\n"
          "key H\n"  // hard shadows off
          "wait_render\n"
          "screenshot noshadows.png\n"
          "key =\nkey =\n"  // two more reflections
          "wait_render\n"
          "screenshot reflections.png\n"
          "screenshot_window window.png\n"
          "quit\n");
    const RunResult r = view(scene + " --size 320x180 --internal-size 320x180 --script fly.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Image start = png("start.png"), moved = png("moved.png"), edited = png("edited.png");
    ASSERT_EQ(start.width(), 320);
    // Terrain, not just sky: many pixels whose blue channel does not dominate.
    int ground = 0;
    for (int y = 0; y < start.height(); ++y) {
        for (int x = 0; x < start.width(); ++x) {
            const luxel::Rgb c = start.rgb(x, y);
            if (c.b < std::max(c.r, c.g)) ++ground;
        }
    }
    EXPECT_GT(ground, static_cast<int>(start.pixelCount() / 5)) << "ground pixels: " << ground;
    EXPECT_GT(meanAbsDiff(start, moved), 0.01);  // W moved the camera
    // The click removed the voxel under the pointer: the picture changes there.
    EXPECT_GT(std::fabs(regionMean(moved, 160, 120, 6) - regionMean(edited, 160, 120, 6)), 1e-4);
    // Without shadows nothing gets darker; with more reflections the picture changes.
    const Image noShadows = png("noshadows.png"), reflections = png("reflections.png");
    EXPECT_GT(regionMean(noShadows, 160, 90, 200), regionMean(edited, 160, 90, 200));
    EXPECT_GT(meanAbsDiff(noShadows, reflections), 1e-3);
}

TEST_F(ViewerXvfb, BadInputGivesOneClearLineAndExitCode1) {
    const std::string scene = write("lamp.json", kLampScene);
    write("bad.txt", "wait_render\nkey NoSuchKey\n");
    RunResult r = view(scene + " --script bad.txt");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("bad.txt:2: key: unknown key 'NoSuchKey'"), std::string::npos)
        << r.output;
    r = view(path("missing.json"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel-view: error: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("missing.json"), std::string::npos) << r.output;
    write("broken.json", "{\"canvas\": [64, 64], \"shapes\": [}");
    r = view(path("broken.json"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("broken.json:1:"), std::string::npos) << r.output;
}

TEST_F(ViewerXvfb, NoDisplayIsAClearErrorNotACrash) {
    const std::string scene = write("lamp.json", kLampScene);
    const RunResult r = run("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER timeout 60 " +
                            std::string(LUXEL_VIEW_PATH) + " " + scene);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("luxel-view: error: cannot open a window"), std::string::npos)
        << r.output;
}

TEST_F(ViewerXvfb, GpuBackendMatchesTheCpuPicture) {
    auto devices = luxel::gpu::listDevices();
    if (!devices || devices->empty()) GTEST_SKIP() << "no Vulkan device";
    const std::string scene = write("lamp.json", kLampScene);
    write("shot.txt", "wait_render\nscreenshot shot.png\nquit\n");
    RunResult r =
        view(scene + " --size 256x256 --internal-size 128x128 --backend gpu --script shot.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("backend gpu"), std::string::npos) << r.output;
    fs::rename(path("shot.png"), path("gpu.png"));
    r = view(scene + " --size 256x256 --internal-size 128x128 --backend cpu --script shot.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("backend cpu"), std::string::npos) << r.output;
    EXPECT_LT(meanAbsDiff(png("gpu.png"), png("shot.png")), 0.01);
}

TEST_F(ViewerXvfb, VoxelGpuBackendMatchesTheCpuAndShowsEdits) {
    auto devices = luxel::gpu::listDevices();
    if (!devices || devices->empty()) GTEST_SKIP() << "no Vulkan device";
    const std::string scene = write("terrain.json", kVoxelScene);
    write("edit.txt",
          "wait_render\n"
          "screenshot before.png\n"
          "click 160 120\n"
          "wait_render\n"
          "screenshot after.png\n"
          "quit\n");
    const std::string size = " --size 320x180 --internal-size 320x180 --script edit.txt";
    RunResult r = view(scene + size + " --backend gpu");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("backend gpu"), std::string::npos) << r.output;
    fs::rename(path("before.png"), path("gpu-before.png"));
    fs::rename(path("after.png"), path("gpu-after.png"));
    r = view(scene + size + " --backend cpu");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("backend cpu"), std::string::npos) << r.output;
    // The same pictures before and after the edit (re-uploaded chunk on the GPU).
    const Image gpuBefore = png("gpu-before.png"), gpuAfter = png("gpu-after.png");
    EXPECT_LT(meanAbsDiff(gpuBefore, png("before.png")), 0.002);
    EXPECT_LT(meanAbsDiff(gpuAfter, png("after.png")), 0.002);
    EXPECT_GT(std::fabs(regionMean(gpuBefore, 160, 120, 6) - regionMean(gpuAfter, 160, 120, 6)),
              1e-4);
}

}  // namespace
