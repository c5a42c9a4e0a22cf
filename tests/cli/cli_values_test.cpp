// Numeric option values and input files the `luxel` command line must refuse: out-of-range,
// overflowing and non-finite numbers (one line naming the option), and files that are not regular
// files (a FIFO would block the reader forever).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <sys/stat.h>

#include "support/cli_fixture.h"

namespace {

class CliValues : public luxel::test::CliFixture {
  protected:
    std::string scene() {
        return write("small.json", R"({"canvas": [16, 16], "shapes": [
            {"type": "circle", "center": [8, 8], "radius": 3, "emission": [1, 1, 1]}]})");
    }
    std::string render(const std::string& flags) {
        return "render " + scene() + " --out " + path("out.exr") + " " + flags;
    }
    std::string fifo(const std::string& name) {
        const std::string p = path(name);
        EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0) << p;
        return p;
    }
    // Opening a FIFO for reading waits for a writer: `timeout` turns a hang into exit 124.
    void expectNotRegular(const std::string& args,
                          const std::string& needle = "not a regular file") {
        const luxel::test::RunResult r =
            luxel::test::runCommand("timeout 20 " + std::string(LUXEL_CLI_PATH) + " " + args);
        EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("luxel: error: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(needle), std::string::npos) << r.output;
    }
};

TEST_F(CliValues, OverflowingSizesAreRefusedNotWrapped) {
    expectError(render("--size 4294967297x1"), "--size '4294967297x1'");
    expectError(render("--size 99999999999999999999x2"), "--size '99999999999999999999x2'");
    expectError(render("--size 65537x1"), "each side must be in 1..65536");
    expectError(render("--size -1x2"), "--size '-1x2' is not WIDTHxHEIGHT");
}

TEST_F(CliValues, NonFiniteFloatOptionsAreRefused) {
    expectError(render("--exposure nan --png " + path("out.png")),
                "--exposure: 'nan' is not a finite number in [-64, 64]");
    expectError(render("--exposure inf"), "--exposure: 'inf' is not a finite number");
    expectError(render("--exposure 1e400"), "--exposure: '1e400'");
    expectError(render("--bloom nan"), "--bloom: 'nan' is not a finite number in [0, 1]");
    expectError(render("--sharpness nan"), "--sharpness: 'nan'");
    expectError(render("--internal-scale nan"), "--internal-scale: 'nan'");
    expectError(render("--base-interval inf"), "--base-interval: 'inf'");
    expectError("upscale " + scene() + " --scale nan", "--scale: 'nan'");
    expectError("compare a.exr b.exr --diff-scale nan", "--diff-scale: 'nan'");
    expectError("shadows " + scene() + " --sun-step nan", "--sun-step: 'nan'");
    expectError("shadows " + scene() + " --sun-radius inf", "--sun-radius: 'inf'");
    expectError("shadows " + scene() + " --blend-band nan,2", "--blend-band: 'nan'");
    expectError("octree convert in.vdb out.lxo --max nan", "--max: 'nan'");
    expectError("octree convert in.vdb out.lxo --max -1", "--max: '-1'");
}

TEST_F(CliValues, WholeNumberOptionsAreRangeChecked) {
    expectError(render("--threads -5"), "--threads: '-5' is not a whole number in 0..4096");
    expectError(render("--threads 99999999999999999999"), "--threads: '99999999999999999999'");
    expectError(render("--threads two"), "--threads: 'two'");
    expectError(render("--rays 0"), "--rays: '0' is not a whole number in 1..1048576");
    expectError(render("--supersample 0"), "--supersample: '0'");
    expectError(render("--probe-spacing 0"), "--probe-spacing: '0'");
    expectError(render("--max-cascades 17"), "--max-cascades: '17'");
    expectError(render("--samples -1"), "--samples: '-1'");
    expectError("raster " + scene() + " --supersample 65", "--supersample: '65'");
    expectError("info " + scene() + " --rays -1", "--rays: '-1'");
    expectError("compare-solvers " + scene() + " --rays 0", "--rays: '0'");
    expectError("bench " + scene() + " --repeat 0", "--repeat: '0'");
    expectError("octree tiles " + scene() + " --tile-bits 0", "--tile-bits: '0'");
}

TEST_F(CliValues, InRangeValuesStillRender) {
    const luxel::test::RunResult r =
        luxel::test::runLuxel(render("--threads 2 --rays 8 --solver reference --exposure -1.5 -q"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST_F(CliValues, FifosAndFoldersAreNotRead) {
    expectNotRegular("render " + fifo("scene.json") + " --out " + path("out.exr"));
    expectNotRegular("info " + path("scene.json"));
    expectNotRegular("compare " + fifo("a.png") + " " + fifo("b.png"));
    expectNotRegular("compare " + fifo("a.exr") + " " + path("a.png"));
    expectNotRegular("info " + dir().string(), "Is a directory");
    std::filesystem::create_directory(path("folder.png"));
    expectNotRegular("compare " + path("folder.png") + " " + path("a.png"), "Is a directory");
}

}  // namespace
