// `luxel` on octree scenes end to end: render, info and bench on the CPU, `octree build` and
// `octree convert` to and from .lxo files, and bad input refused with one located line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/octree/octree_file.h"
#include "support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliOctree : public luxel::test::CliFixture {};

// A 32^3 box world: a floor and a pillar, seen from above the floor.
const char* kBoxWorldScene = R"({
  "type": "octree",
  "octree": {"source": "world", "world": {"source": "empty", "size": [32, 32, 32], "shapes": [
    {"type": "box", "min": [0, 0, 0], "max": [32, 4, 32], "color": [120, 200, 90]},
    {"type": "box", "min": [12, 4, 12], "max": [18, 20, 18], "color": [200, 60, 40]}]}},
  "camera": {"position": [16, 26, -20], "look_at": [16, 8, 16], "fov": 50, "size": [64, 48]},
  "render": {"mode": "surface", "sun_direction": [0.3, 1, 0.2]}
})";

TEST_F(CliOctree, RenderInfoAndBenchOnTheCpu) {
    const std::string scene = write("box.json", kBoxWorldScene);
    RunResult r = runLuxel("render " + scene + " --backend cpu --out " + path("box.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("surface mode, image 64x48, cpu"), std::string::npos) << r.output;
    auto image = luxel::readPng(path("box.png"));
    ASSERT_TRUE(image.ok()) << image.error().message();
    EXPECT_EQ(image->width(), 64);
    // The pillar's red face is in the middle of the picture; the floor is green below it.
    EXPECT_GT(image->at(32, 24, 0), image->at(32, 24, 1)) << "red pillar at the centre";
    EXPECT_GT(image->at(32, 45, 1), image->at(32, 45, 0)) << "green floor at the bottom";

    r = runLuxel("info " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("depth 5 (32^3)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bits per voxel"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("surface mode"), std::string::npos) << r.output;

    r = runLuxel("bench " + scene + " --backend cpu --sizes 32x24 --repeat 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("32x24"), std::string::npos) << r.output;
}

TEST_F(CliOctree, BuildWritesAContainerThatAFileSceneRendersAlike) {
    const std::string scene = write("box.json", kBoxWorldScene);
    RunResult r = runLuxel("octree build " + scene + " --out " + path("box.lxo"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("bits per solid voxel"), std::string::npos) << r.output;
    auto tree = luxel::octree::readOctreeFile(path("box.lxo"));
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    EXPECT_EQ(tree->depth, 5);
    EXPECT_TRUE(tree->hasColours());

    r = runLuxel("octree convert " + path("box.lxo") + " " + path("copy.lxo"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto copy = luxel::octree::readOctreeFile(path("copy.lxo"));
    ASSERT_TRUE(copy.ok()) << copy.error().message();
    // Compaction may reorder the octants; the voxels are the same.
    const auto before = luxel::octree::measure(*tree), after = luxel::octree::measure(*copy);
    EXPECT_EQ(after.solidVoxels, before.solidVoxels);
    EXPECT_EQ(after.reachable, before.reachable);
    for (int i = 0; i < 32 * 32 * 32; i += 7) {
        const luxel::Int3 cell(i % 32, (i / 32) % 32, i / 1024);
        ASSERT_EQ(luxel::octree::opacityAt(*copy, cell), luxel::octree::opacityAt(*tree, cell));
        ASSERT_EQ(luxel::octree::colourAt(*copy, cell), luxel::octree::colourAt(*tree, cell));
    }

    const std::string fromFile = write("file.json", R"({
      "type": "octree", "octree": {"source": "file", "path": "box.lxo"},
      "camera": {"position": [16, 26, -20], "look_at": [16, 8, 16], "fov": 50, "size": [64, 48]},
      "render": {"mode": "surface", "sun_direction": [0.3, 1, 0.2]}})");
    ASSERT_EQ(runLuxel("render " + scene + " --backend cpu --out " + path("a.exr")).exitCode, 0);
    r = runLuxel("render " + fromFile + " --backend cpu --out " + path("b.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto a = luxel::readExr(path("a.exr"));
    auto b = luxel::readExr(path("b.exr"));
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_EQ(a->width(), b->width());
    const std::size_t floats = static_cast<std::size_t>(a->width()) * a->height() * 3;
    EXPECT_TRUE(std::equal(a->data(), a->data() + floats, b->data()))
        << "the container holds the same tree";
}

// The WebGL octree design's tiles against the exact walk: the loss table and both frame times, and
// "tiles" as a scene's render mode.
TEST_F(CliOctree, TilesReportsItsLossesAndIsARenderMode) {
    const std::string scene = write("box.json", kBoxWorldScene);
    RunResult r = runLuxel("octree tiles " + scene + " --backend cpu --repeat 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* line :
         {"tiles of 8^3 cells, 2 passes", "exact traversal hits a surface",
          "tiles miss a surface (lost)", "frame, exact traversal", "frame, tiles (2 passes)"}) {
        EXPECT_NE(r.output.find(line), std::string::npos) << line << " in:\n" << r.output;
    }
    std::string tiles = kBoxWorldScene;
    tiles.replace(tiles.find("\"surface\""), 9, "\"tiles\"");
    r = runLuxel("render " + write("tiles.json", tiles) + " --backend cpu --out " +
                 path("tiles.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("tiles mode"), std::string::npos) << r.output;
    expectError("octree tiles " + scene + " --tile-bits 0", "tile");
}

TEST_F(CliOctree, BadInputIsRefusedWithItsLocation) {
    const std::string badSource = write("bad.json", R"({"type": "octree",
  "octree": {"source": "cloud"}, "camera": {"position": [0, 0, 0], "yaw": 0, "pitch": 0,
  "fov": 40, "size": [8, 8]}})");
    expectError("render " + badSource + " --out " + path("x.png"), "octree.source");
    expectError("render " + badSource + " --out " + path("x.png"), "bad.json:2:");
    const std::string missing = write("missing.json", R"({"type": "octree",
  "octree": {"source": "file", "path": "nowhere.lxo"}, "camera": {"position": [0, 0, 0],
  "yaw": 0, "pitch": 0, "fov": 40, "size": [8, 8]}})");
    expectError("info " + missing, "nowhere.lxo");
    const std::string window = write("window.json", R"({"type": "octree",
  "octree": {"source": "phantom", "size": 8}, "camera": {"position": [0, 0, 0], "yaw": 0,
  "pitch": 0, "fov": 40, "size": [8, 8]}, "render": {"opacity_window": [200, 100]}})");
    expectError("info " + window, "render.opacity_window: must be [low, high]");
    const std::string scene = write("box.json", kBoxWorldScene);
    expectError("render " + scene + " --solver hrc --out " + path("x.png"), "an octree scene");
    expectError("octree build " + scene + " --out " + path("x.bin"), "must end in .lxo");
    write("junk.lxo", "LXOCTREE but not really");
    expectError("octree convert " + path("junk.lxo") + " " + path("y.lxo"), "junk.lxo");
    EXPECT_FALSE(fs::exists(path("y.lxo")));
}

}  // namespace
