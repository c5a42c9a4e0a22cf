// Memory refusals end to end: under a low address-space limit (`ulimit -v`) `luxel render` and
// `luxel info` refuse the same sizes with the same one line, and whatever the limit, luxel ends
// with exit code 0 or 1 and never aborts on std::bad_alloc.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "support/cli_fixture.h"

namespace {

using luxel::test::RunResult;

// ASan reserves terabytes of shadow address space, so an address-space limit cannot apply to a
// sanitised luxel.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// `luxel args` with its address space limited to `kib` KiB.
RunResult runLimited(long kib, const std::string& args) {
    return luxel::test::runCommand("ulimit -v " + std::to_string(kib) + " && " +
                                   std::string(LUXEL_CLI_PATH) + " " + args);
}

std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

class CliMemory : public luxel::test::CliFixture {
  protected:
    void SetUp() override {
        if (kSanitized) GTEST_SKIP() << "address-space limits do not apply under ASan";
        CliFixture::SetUp();
    }
    // A run that must refuse with exit 1 and exactly the line `expected`.
    void expectRefusal(const RunResult& r, const std::string& expected) {
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_EQ(r.output.rfind(expected, 0), 0u) << r.output;
        EXPECT_NE(r.output.find(" is available\n"), std::string::npos) << r.output;
        EXPECT_EQ(lines(r.output), 1u) << r.output;
    }
};

constexpr long kLimitKiB = 3 * 1024 * 1024;  // 3 GiB: far below any of the sizes refused here
const std::string kTerrain = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json";

TEST_F(CliMemory, VoxelRenderAndInfoRefuseTheSameSize) {
    const std::string line = "luxel: error: rendering 65536x65536 needs ";
    expectRefusal(
        runLimited(kLimitKiB, "render " + kTerrain + " --backend cpu --size 65536x65536 --out " +
                                  path("v.png")),
        line);
    EXPECT_FALSE(std::filesystem::exists(path("v.png")));
    const RunResult info = runLimited(kLimitKiB, "info " + kTerrain + " --size 65536x65536");
    EXPECT_EQ(info.exitCode, 1) << info.output;
    EXPECT_NE(info.output.find("memory (cpu)"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find(line), std::string::npos) << info.output;
    // A size that fits renders under the same limit.
    const RunResult small =
        runLimited(kLimitKiB, "render " + kTerrain + " --backend cpu --size 64x48 --quiet --out " +
                                  path("s.png"));
    EXPECT_EQ(small.exitCode, 0) << small.output;
    EXPECT_TRUE(std::filesystem::exists(path("s.png")));
}

// At 6000x6000 the frames fit under the limit and the path tracer's 2.1 GiB of running sums on
// top do not: render refuses, and info's path line says so.
TEST_F(CliMemory, PathRenderAndInfoAgreeOnTheRunningSums) {
    expectRefusal(runLimited(kLimitKiB, "render " + kTerrain +
                                            " --solver path --backend cpu --size 6000x6000 --out " +
                                            path("p.exr")),
                  "luxel: error: rendering 6000x6000 needs ");
    const RunResult info = runLimited(kLimitKiB, "info " + kTerrain + " --size 6000x6000");
    EXPECT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("running sums of 6000x6000 pixels (over the limit: luxel render "
                               "--solver path refuses it)\n"),
              std::string::npos)
        << info.output;
    const RunResult fits = runLimited(kLimitKiB, "info " + kTerrain + " --size 640x360");
    EXPECT_NE(fits.output.find("running sums of 640x360 pixels\n"), std::string::npos)
        << fits.output;
}

TEST_F(CliMemory, TwoDimensionalRenderAndInfoRefuseTheSameSizeForEverySolver) {
    const std::string scene = write("small.json", R"({"canvas": [48, 32], "shapes": [
        {"type": "circle", "center": [12, 16], "radius": 5, "emission": 2, "opaque": true}]})");
    for (const char* solver : {"reference", "hrc", "rc"}) {
        const std::string line =
            std::string("luxel: error: rendering 32768x32768 with ") + solver + " needs ";
        expectRefusal(
            runLimited(kLimitKiB, "render " + scene + " --solver " + solver +
                                      " --backend cpu --size 32768x32768 --out " + path("x.exr")),
            line);
        const RunResult info =
            runLimited(kLimitKiB, "info " + scene + " --solver " + solver + " --size 32768x32768");
        EXPECT_EQ(info.exitCode, 1) << info.output;
        EXPECT_NE(info.output.find(line), std::string::npos) << info.output;
    }
}

TEST_F(CliMemory, OctreeRenderAndInfoRefuseTheSameSize) {
    const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/octree/world.json";
    if (!std::filesystem::exists(scene)) GTEST_SKIP() << "no shipped octree world scene";
    const std::string line = "luxel: error: rendering 65536x65536 needs ";
    expectRefusal(
        runLimited(kLimitKiB,
                   "render " + scene + " --backend cpu --size 65536x65536 --out " + path("o.png")),
        line);
    const RunResult info = runLimited(kLimitKiB, "info " + scene + " --size 65536x65536");
    EXPECT_EQ(info.exitCode, 1) << info.output;
    EXPECT_NE(info.output.find(line), std::string::npos) << info.output;
}

// The lowest limit (in steps of `step` KiB) at which luxel gets through its libraries' static
// initialisers to main: below it the dynamic loader, or a library starting a thread before main,
// fails where nothing of luxel's can catch it.
long startupFloorKiB(long step) {
    for (long kib = step; kib <= 4 * 1024 * 1024; kib += step) {
        if (runLimited(kib, "--version").exitCode == 0) return kib;
    }
    return 0;
}

// From the limit where luxel can barely start to one where the render fits, every run succeeds
// or ends with exit code 1 and one "luxel: error:" line: a refusal by an estimate, or the last
// resort for std::bad_alloc (and a thread that cannot start), never SIGABRT.
TEST_F(CliMemory, NoLimitEndsInAnAbort) {
    constexpr long kStep = 8 * 1024;
    const long floor = startupFloorKiB(kStep);
    ASSERT_GT(floor, 0) << "luxel --version does not run under 4 GiB of address space";
    int refused = 0, rendered = 0;
    for (long kib = floor; kib <= floor + 30 * kStep; kib += kStep) {
        const RunResult r = runLimited(kib, "render " + kTerrain +
                                                " --backend cpu --threads 2 --size 512x384 "
                                                "--quiet --out " +
                                                path("t.png"));
        ASSERT_LT(r.exitCode, 2) << "limit " << kib << " KiB:\n" << r.output;
        if (r.exitCode == 0) {
            ++rendered;
            continue;
        }
        ++refused;
        EXPECT_EQ(r.output.rfind("luxel: error: ", 0), 0u) << kib << " KiB:\n" << r.output;
        EXPECT_EQ(lines(r.output), 1u) << kib << " KiB:\n" << r.output;
    }
    EXPECT_GT(refused, 0) << "no limit was low enough to refuse";
    EXPECT_GT(rendered, 0) << "no limit was high enough to render";
}

}  // namespace
