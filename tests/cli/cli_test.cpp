// The `luxel` command line end to end: valid runs write files, bad input gives one clear line on
// stderr and a non-zero exit, never a crash.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/gi2d/medium2d.h"
#include "support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;

using luxel::test::RunResult;

RunResult runLuxel(const std::string& args, const std::string& environment = "") {
    return luxel::test::runCommand(environment + (environment.empty() ? "" : " ") + LUXEL_CLI_PATH +
                                   " " + args);
}

class Cli : public luxel::test::CliFixture {};

const char* kSmallScene = R"({
  "canvas": [48, 32],
  "background": {"absorption": 0.01},
  "shapes": [
    {"type": "circle", "center": [12, 16], "radius": 5, "emission": [2, 1, 0.5], "opaque": true},
    {"type": "box", "min": [24, 4], "max": [28, 20], "opaque": true}
  ]
})";

TEST_F(Cli, RenderWritesExrAndDisplayPngAndPrintsTimings) {
    const std::string scene = write("small.json", kSmallScene);
    const RunResult r =
        runLuxel("render " + scene + " --solver reference --rays 64 --threads 2 --out " +
                 path("f.exr") + " --png " + path("d.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Mrays/s"), std::string::npos) << r.output;
    auto fluence = luxel::readExr(path("f.exr"));
    ASSERT_TRUE(fluence.ok()) << fluence.error().message();
    EXPECT_EQ(fluence->width(), 48);
    EXPECT_EQ(fluence->height(), 32);
    EXPECT_GT(fluence->at(16, 16, 0), fluence->at(40, 16, 0)) << "shadow behind the box";
    auto display = luxel::readPng(path("d.png"));
    ASSERT_TRUE(display.ok());
    EXPECT_EQ(display->width(), 48);
}

TEST_F(Cli, RenderAtAnotherSizeAndPngOutput) {
    const std::string scene = write("small.json", kSmallScene);
    const RunResult r =
        runLuxel("render " + scene + " --size 30x20 --rays 16 --quiet --out " + path("f.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(r.output.empty()) << r.output;
    auto img = luxel::readPng(path("f.png"));
    ASSERT_TRUE(img.ok());
    EXPECT_EQ(img->width(), 30);
    EXPECT_EQ(img->height(), 20);
}

TEST_F(Cli, RasterCompareAndInfo) {
    const std::string scene = write("small.json", kSmallScene);
    RunResult r = runLuxel("raster " + scene + " --emission " + path("e.exr") + " --absorption " +
                           path("a.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto e = luxel::readExr(path("e.exr"));
    ASSERT_TRUE(e.ok());
    EXPECT_NEAR(e->at(12, 16, 0), 2.0f, 1e-5);

    r = runLuxel("compare " + path("e.exr") + " " + path("e.exr") + " --diff " + path("diff.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("RMSE          0"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(path("diff.png")));

    r = runLuxel("compare " + path("e.exr") + " " + path("a.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("relative L1"), std::string::npos);

    r = runLuxel("info " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("48x32"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("circle"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("memory"), std::string::npos) << r.output;
}

TEST_F(Cli, MalformedJsonReportsLineAndColumn) {
    const std::string scene =
        write("bad.json", "{\n  \"canvas\": [48, 32],\n  \"shapes\": [,]\n}\n");
    expectError("render " + scene + " --out " + path("x.exr"), "bad.json:3:");
}

TEST_F(Cli, UnknownShapeTypeAndField) {
    std::string scene = write("t.json", R"({"canvas": [8, 8], "shapes": [{"type": "triangle"}]})");
    expectError("render " + scene + " --out " + path("x.exr"), "unknown shape type 'triangle'");
    scene = write(
        "f.json",
        R"({"canvas": [8, 8], "shapes": [{"type": "circle", "center": [1, 1], "radiuss": 2}]})");
    expectError("info " + scene, "radiuss");
}

TEST_F(Cli, BadSizes) {
    const std::string scene = write("small.json", kSmallScene);
    expectError("render " + scene + " --size 0x10 --out " + path("x.exr"),
                "--size '0x10': each side must be in 1..65536");
    expectError("render " + scene + " --size -5x10 --out " + path("x.exr"),
                "--size '-5x10' is not WIDTHxHEIGHT");
    expectError("render " + scene + " --size 100000x100000 --out " + path("x.exr"),
                "--size '100000x100000': each side must be in 1..65536");
    expectError("render " + scene + " --size banana --out " + path("x.exr"), "WIDTHxHEIGHT");
    const std::string zero = write("zero.json", R"({"canvas": [0, 32], "shapes": []})");
    expectError("render " + zero + " --out " + path("x.exr"), "canvas");
}

TEST_F(Cli, NanAndNegativeEmission) {
    std::string scene = write(
        "neg.json",
        R"({"canvas": [8, 8], "shapes": [{"type": "circle", "center": [4, 4], "radius": 2, "emission": [1, -1, 0]}]})");
    expectError("render " + scene + " --out " + path("x.exr"), "emission");
    scene = write(
        "nan.json",
        R"({"canvas": [8, 8], "shapes": [{"type": "circle", "center": [4, 4], "radius": 2, "emission": NaN}]})");
    expectError("render " + scene + " --out " + path("x.exr"), "nan.json:1:");
    scene = write(
        "inf.json",
        R"({"canvas": [8, 8], "shapes": [{"type": "circle", "center": [4, 4], "radius": 2, "emission": 1e999}]})");
    expectError("render " + scene + " --out " + path("x.exr"), "finite");
}

TEST_F(Cli, MissingFiles) {
    expectError("render " + path("nope.json") + " --out " + path("x.exr"), "nope.json");
    const std::string scene =
        write("img.json",
              R"({"canvas": [8, 8], "shapes": [{"type": "image", "emission": "missing.png"}]})");
    expectError("render " + scene + " --out " + path("x.exr"), "missing.png");
    expectError("compare " + path("a.exr") + " " + path("b.exr"), "a.exr");
}

TEST_F(Cli, OtherBadArguments) {
    const std::string scene = write("small.json", kSmallScene);
    expectError("render " + scene + " --solver magic --out " + path("x.exr"),
                "--solver 'magic' is not one of: reference, hrc, rc");
    expectError("render " + scene + " --solver rc --merge nearest --out " + path("x.exr"),
                "--merge 'nearest' is not one of: vanilla, bilinear-fix");
    expectError("info " + scene + " --solver magic", "--solver 'magic' is not one of");
    expectError("bench " + scene + " --backend auto", "--backend 'auto' is not cpu or gpu");
    expectError("render " + scene + " --out " + path("x.tiff"), ".exr or .png");
    expectError("render " + scene + " --rays 0 --out " + path("x.exr"),
                "--rays: '0' is not a whole number in 1..");
    const RunResult r = runLuxel("render");  // CLI11 usage error: non-zero, no crash
    EXPECT_NE(r.exitCode, 0);
    EXPECT_LT(r.exitCode, 128) << r.output;
}

TEST_F(Cli, SceneTooLargeForMemoryIsRefused) {
    const std::string scene = write("small.json", kSmallScene);
    const std::uint64_t needed = luxel::gi2d::mediumBytes(65536, 65536);
    if (luxel::availableMemoryBytes() > needed) GTEST_SKIP() << "this machine has the memory";
    expectError("render " + scene + " --size 65536x65536 --out " + path("x.exr"), "only");
}

TEST_F(Cli, RcVariantsMarchersAndViews) {
    const std::string scene = write("small.json", kSmallScene);  // has a faint medium: DDA only
    RunResult r = runLuxel("render " + scene + " --solver rc --out " + path("v.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("merge bilinear-fix, march dda"), std::string::npos) << r.output;
    r = runLuxel("render " + scene + " --solver rc --merge bilinear-fix --out " + path("f.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto f = luxel::readExr(path("f.exr"));
    ASSERT_TRUE(f.ok());
    EXPECT_GT(f->at(16, 16, 0), f->at(40, 16, 0)) << "shadow behind the box";
    expectError("render " + scene + " --solver rc --march sdf --out " + path("x.exr"), "SDF");
    expectError("render " + scene + " --solver rc --merge magic --out " + path("x.exr"), "--merge");
    r = runLuxel("render " + scene + " --solver rc --jitters 3 --out " + path("j.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("3 jittered probe grids"), std::string::npos) << r.output;
    auto j = luxel::readExr(path("j.exr"));
    ASSERT_TRUE(j.ok());
    EXPECT_NE(j->at(20, 20, 0), f->at(20, 20, 0)) << "jittered grids change the image";
    expectError("render " + scene + " --solver rc --jitters 0 --out " + path("x.exr"), "--jitters");
    expectError("render " + scene + " --solver rc --view sideways --out " + path("x.exr"),
                "--view");
    const std::string shapes = write("shapes.json", R"({"canvas": [40, 30], "shapes": [
        {"type": "circle", "center": [10, 15], "radius": 4, "emission": 2, "opaque": true}]})");
    // All shapes opaque: auto still traces the shared pixel medium; sdf only when asked, and says
    // so.
    r = runLuxel("render " + shapes + " --solver rc --out " + path("s.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("march dda"), std::string::npos) << r.output;
    r = runLuxel("render " + shapes + " --solver rc --march sdf --out " + path("s.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("march sdf (exact shapes, not the rasterised medium"),
              std::string::npos)
        << r.output;
    r = runLuxel("render " + shapes + " --solver rc --view probes --cascade 1 --quiet --out " +
                 path("p.exr") + " --png " + path("p.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto probes = luxel::readPng(path("p.png"));
    ASSERT_TRUE(probes.ok());
    EXPECT_GT(probes->at(1, 1, 0), 0.5f) << "cascade-1 probe at (1, 1) is marked";
    r = runLuxel("render " + shapes + " --view nogi --quiet --out " + path("n.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto dark = luxel::readExr(path("n.exr"));
    ASSERT_TRUE(dark.ok());
    EXPECT_EQ(dark->at(30, 15, 0), 0.0f);
}

TEST_F(Cli, CompareSolversPrintsOneRowPerSolverAndAGrid) {
    const std::string scene = write("small.json", kSmallScene);
    const RunResult r =
        runLuxel("compare-solvers " + scene + " --rays 64 --grid " + path("grid.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* solver : {"reference", "hrc", "rc-vanilla", "rc-bilinear-fix"}) {
        EXPECT_NE(r.output.find(std::string("\n") + solver + " "), std::string::npos)
            << solver << "\n"
            << r.output;
    }
    EXPECT_NE(r.output.find("MiB"), std::string::npos) << r.output;
    auto grid = luxel::readPng(path("grid.png"));
    ASSERT_TRUE(grid.ok());
    EXPECT_EQ(grid->width(), 4 * 48 + 3 * 4);
    EXPECT_EQ(grid->height(), 32);
    expectError("compare-solvers " + path("none.json"), "none.json");
}

TEST_F(Cli, CompareSolversErrorImageAndMovingLight) {
    const std::string scene = write("small.json", kSmallScene);
    RunResult r =
        runLuxel("compare-solvers " + scene + " --rays 32 --error-image " + path("e.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("\nreference-seed2 "), std::string::npos) << r.output;
    auto errors = luxel::readPng(path("e.png"));
    ASSERT_TRUE(errors.ok());
    EXPECT_EQ(errors->width(), 5 * 48 + 4 * 4);  // reference, seed-2 noise, 3 solvers
    r = runLuxel("compare-solvers " + scene + " --rays 32 --move 0.5,0 --error-image " +
                 path("m.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("change by < 0.1%"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\nrc-bilinear-fix "), std::string::npos) << r.output;
    EXPECT_TRUE(luxel::readPng(path("m.png")).ok());
    expectError("compare-solvers " + scene + " --move sideways", "--move 'sideways'");
    expectError("compare-solvers " + scene + " --error-scale 0", "--error-scale");
}

TEST_F(Cli, DevicesListsVulkanDevicesOrSaysWhyNot) {
    RunResult r = runLuxel("devices");
    if (r.exitCode == 0) {
        EXPECT_NE(r.output.find("device memory"), std::string::npos) << r.output;
    } else {
        EXPECT_NE(r.output.find("luxel: error: "), std::string::npos) << r.output;
    }
    // No driver at all: a clear one-line error, not a crash.
    r = runLuxel("devices", "VK_DRIVER_FILES=/nonexistent.json VK_ICD_FILENAMES=/nonexistent.json");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel: error: "), std::string::npos) << r.output;
}

TEST_F(Cli, GpuBackendForHrcAndBench) {
    const std::string scene = write("small.json", kSmallScene);
    expectError("render " + scene + " --solver hrc --backend quantum --out " + path("x.exr"),
                "--backend");
    expectError("render " + scene + " --solver reference --backend gpu --out " + path("x.exr"),
                "CPU-only");
    if (runLuxel("devices").exitCode != 0) GTEST_SKIP() << "no Vulkan device";
    RunResult r =
        runLuxel("render " + scene + " --solver hrc --backend gpu --out " + path("g.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("gpu: "), std::string::npos) << r.output;
    r = runLuxel("render " + scene + " --solver hrc --backend cpu --out " + path("c.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runLuxel("compare " + path("g.exr") + " " + path("c.exr"));
    const auto at = r.output.find("relative L1");
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_LT(std::stod(r.output.substr(at + 11)), 1e-5) << r.output;
    r = runLuxel("render " + scene + " --solver rc --backend gpu --merge bilinear-fix --out " +
                 path("rg.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("march dda, gpu: "), std::string::npos) << r.output;
    r = runLuxel("bench " + scene + " --backend gpu --sizes 32,48 --repeat 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("merge"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\n    48x48 "), std::string::npos) << r.output;
    // No driver: --backend gpu fails clearly, auto falls back to the CPU.
    const std::string noDriver =
        "VK_DRIVER_FILES=/nonexistent.json VK_ICD_FILENAMES=/nonexistent.json";
    r = runLuxel("render " + scene + " --solver hrc --backend gpu --out " + path("x.exr"),
                 noDriver);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("no Vulkan driver"), std::string::npos) << r.output;
    r = runLuxel("render " + scene + " --solver hrc --out " + path("a.exr"), noDriver);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("note: no Vulkan device"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("; using the CPU"), std::string::npos) << r.output;
}

TEST_F(Cli, RendersVoxelScenes) {
    const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json";
    const RunResult r = runLuxel("render " + scene + " --size 96x54 --out " + path("v.exr") +
                                 " --png " + path("v.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("voxel world 256x96x256"), std::string::npos) << r.output;
    auto img = luxel::readExr(path("v.exr"));
    ASSERT_TRUE(img.ok());
    EXPECT_EQ(img->width(), 96);
    EXPECT_GT(img->at(48, 2, 2), img->at(48, 50, 2)) << "sky above, ground below";
    const std::string bad = write("bad.json", R"({"type": "voxel", "world": {"source": "empty",
        "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0], "pitch": 120}})");
    expectError("render " + bad + " --out " + path("x.png"), "camera.pitch");
    expectError("render " + scene + " --solver hrc --out " + path("x.png"),
                "--solver applies to 2D scenes");
}

TEST_F(Cli, VoxelSurfaceFlagsOverrideTheScene) {
    const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/glass.json";
    const std::string flags = " --size 48x27 --backend cpu -q --out ";
    ASSERT_EQ(runLuxel("render " + scene + flags + path("p.exr")).exitCode, 0);
    const RunResult r = runLuxel("render " + scene + flags + path("c.exr") +
                                 " --lighting classic --specular blinn-phong --fresnel schlick"
                                 " --no-refraction");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto physical = luxel::readExr(path("p.exr"));
    auto classic = luxel::readExr(path("c.exr"));
    ASSERT_TRUE(physical.ok() && classic.ok());
    double difference = 0;
    for (int y = 0; y < 27; ++y) {
        for (int x = 0; x < 48; ++x)
            difference += std::abs(physical->at(x, y, 1) - classic->at(x, y, 1));
    }
    EXPECT_GT(difference, 1.0) << "--lighting classic changes the image";
    expectError("render " + scene + flags + path("x.exr") + " --lighting pbr",
                "--lighting 'pbr' is not classic or physical");
    expectError("render " + scene + flags + path("x.exr") + " --specular phong",
                "--specular 'phong'");
    expectError("render " + scene + flags + path("x.exr") + " --fresnel fast", "--fresnel 'fast'");
}

TEST_F(Cli, InfoDescribesVoxelScenes) {
    const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/garden.json";
    const RunResult r = runLuxel("info " + scene + " --size 320x180");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("40x28x40 voxels in chunks of 8"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("textures           3"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("image              320x180"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("memory (gpu)"), std::string::npos) << r.output;
    // 2D-only commands and options say what the file is instead of a 2D field error
    // (compare-solvers itself compares the voxel renderers: cli_compare_voxel_test.cpp).
    expectError("raster " + scene + " --emission " + path("x.exr"), "a voxel scene");
    expectError("compare-solvers " + scene + " --rays 64", "a voxel scene");
}

TEST_F(Cli, BenchesVoxelScenes) {
    const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/garden.json";
    RunResult r = runLuxel("bench " + scene + " --sizes 64x36,80x45 --repeat 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("voxel ray casting on the cpu"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\n      80x45 "), std::string::npos) << r.output;
    expectError("bench " + scene + " --sizes 64x36,banana", "--sizes");
    expectError("bench " + scene + " --repeat 0", "--repeat");
    if (runLuxel("devices").exitCode != 0) GTEST_SKIP() << "no Vulkan device";
    r = runLuxel("bench " + scene + " --backend gpu --sizes 64x36 --repeat 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("dispatch ms"), std::string::npos) << r.output;
}

// The HRC bench times the exact near field in its own column: zero in vacuum, the gather's time
// in fog dense enough to bound the rays (HRC §12.3).
TEST_F(Cli, BenchShowsTheNearFieldWhereItActs) {
    // The value in `columns` columns after the size: 8 is near, 9 direct.
    const auto column = [](const std::string& output, const std::string& size, int columns) {
        std::istringstream table(output.substr(output.find("\n" + size + " ") + 1));
        std::string label;
        double value = -1;
        table >> label;
        for (int c = 0; c < columns; ++c) table >> value;  // ms .. finish, then near, direct
        return value;
    };
    const auto nearColumn = [&](const std::string& output, const std::string& size) {
        return column(output, size, 8);
    };
    // At 64 px dense-fog's lamps are compact lights, whose direct light (§12.5) would take them
    // from the near field: the near field alone.
    const std::string fog = std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/hard/dense-fog.json";
    RunResult r =
        runLuxel("bench " + fog + " --backend cpu --sizes 64 --repeat 1 --no-direct-light");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_NE(r.output.find("      near "), std::string::npos) << r.output;
    EXPECT_GT(nearColumn(r.output, "    64x64"), 0.0) << r.output;
    const std::string room = std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/room.json";
    r = runLuxel("bench " + room + " --backend cpu --sizes 64 --repeat 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(nearColumn(r.output, "    64x64"), 0.0) << r.output;
    EXPECT_EQ(column(r.output, "    64x64", 9), 0.0) << r.output;  // no compact light
    // The compact lights' direct light where there is one, and not with --no-direct-light.
    const std::string disk = std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/hard/bright-disk.json";
    r = runLuxel("bench " + disk + " --backend cpu --sizes 64 --repeat 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_NE(r.output.find("    direct "), std::string::npos) << r.output;
    EXPECT_GT(column(r.output, "    64x64", 9), 0.0) << r.output;
    r = runLuxel("bench " + disk + " --backend cpu --sizes 64 --repeat 1 --no-direct-light");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(column(r.output, "    64x64", 9), 0.0) << r.output;
}

TEST_F(Cli, HrcRendersAndRefusesSizesThatDoNotFit) {
    const std::string scene = write("small.json", kSmallScene);
    RunResult r = runLuxel("render " + scene + " --solver hrc --out " + path("h.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("solver hrc"), std::string::npos) << r.output;
    auto f = luxel::readExr(path("h.exr"));
    ASSERT_TRUE(f.ok());
    EXPECT_GT(f->at(16, 16, 0), f->at(40, 16, 0)) << "shadow behind the box";
    r = runLuxel("render " + scene +
                 " --solver hrc --frustum +x --view cascade --cascade 1 --no-blur "
                 "--traced-levels 1 --out " +
                 path("d.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectError("render " + scene + " --solver hrc --frustum up --out " + path("x.exr"),
                "--frustum");
    r = runLuxel("info " + scene + " --solver hrc --size 1024x1024");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("10 cascades"), std::string::npos) << r.output;

    // 16384^2 needs the medium and the solve, about 16 GiB (writing the images adds no copy of
    // them): it fits a 24 GB machine (docs/performance.md), and is refused where less is there.
    r = runLuxel("info " + scene + " --solver hrc --size 16384x16384");
    const std::size_t all = r.output.find(" GiB in all with the hrc solver");
    ASSERT_NE(all, std::string::npos) << r.output;
    const std::size_t from = r.output.rfind(", ", all) + 2;
    const double gib = std::stod(r.output.substr(from, all - from));
    EXPECT_GE(gib, 15.75) << r.output;  // 5.25 images of 3 GiB at least
    EXPECT_LT(gib, 24e9 / (1 << 30) - 1.0) << r.output;
#if !defined(__SANITIZE_ADDRESS__)  // ASan's shadow memory needs more address space than this
    const std::string limited = "ulimit -v " + std::to_string(12 << 20) + " && " LUXEL_CLI_PATH " ";
    r = luxel::test::runCommand(limited + "render " + scene +
                                " --solver hrc --size 16384x16384 --out " + path("x.exr"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel: error: rendering 16384x16384 with hrc needs"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("only"), std::string::npos) << r.output;
    r = luxel::test::runCommand(limited + "info " + scene +
                                " --solver hrc --size 16384x16384");  // prints, then refuses
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("luxel: error: rendering 16384x16384 with hrc needs"),
              std::string::npos)
        << r.output;
#endif
}

}  // namespace
