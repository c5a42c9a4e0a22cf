// `luxel render --bounces` and `luxel info` on scenes with albedo.
#include <gtest/gtest.h>

#include <string>

#include "luxel/core/image_io.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::RunResult;

RunResult runLuxel(const std::string& args) {
    return luxel::test::runCommand(std::string(LUXEL_CLI_PATH) + " " + args);
}

class CliBounce : public luxel::test::CliFixture {};

// A light in a closed room whose walls reflect half of what arrives.
const char* kRoom = R"({
  "canvas": [32, 32],
  "shapes": [
    {"type": "box", "min": [0, 0], "max": [32, 3], "opaque": true, "albedo": 0.5},
    {"type": "box", "min": [0, 29], "max": [32, 32], "opaque": true, "albedo": 0.5},
    {"type": "box", "min": [0, 3], "max": [3, 29], "opaque": true, "albedo": 0.5},
    {"type": "box", "min": [29, 3], "max": [32, 29], "opaque": true, "albedo": 0.5},
    {"type": "circle", "center": [16, 16], "radius": 3, "emission": 2, "opaque": true}
  ]
})";

double meanRed(const luxel::Image& image) {
    double sum = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) sum += image.at(x, y, 0);
    return sum / image.pixelCount();
}

TEST_F(CliBounce, BouncesBrightenTheRoomAndAreReported) {
    const std::string scene = write("room.json", kRoom);
    const RunResult off = runLuxel(
        "render " + scene + " --solver hrc --backend cpu --bounces 0 --out " + path("off.exr"));
    ASSERT_EQ(off.exitCode, 0) << off.output;
    const RunResult on = runLuxel("render " + scene +
                                  " --solver hrc --backend cpu --bounces 3 "
                                  "--out " +
                                  path("on.exr"));
    ASSERT_EQ(on.exitCode, 0) << on.output;
    EXPECT_NE(on.output.find("3 bounces"), std::string::npos) << on.output;
    const RunResult ref = runLuxel("render " + scene + " --rays 32 --out " + path("ref.exr"));
    ASSERT_EQ(ref.exitCode, 0) << ref.output;
    EXPECT_NE(ref.output.find("converged"), std::string::npos) << ref.output;
    auto a = luxel::readExr(path("off.exr"));
    auto b = luxel::readExr(path("on.exr"));
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_GT(meanRed(*b), 1.2 * meanRed(*a));
}

TEST_F(CliBounce, InfoSaysWhetherASceneBounces) {
    const RunResult yes = runLuxel("info " + write("room.json", kRoom));
    ASSERT_EQ(yes.exitCode, 0) << yes.output;
    EXPECT_NE(yes.output.find("bounce light       yes"), std::string::npos) << yes.output;
    const RunResult no = runLuxel("info " + write("plain.json", R"({"canvas": [8, 8]})"));
    ASSERT_EQ(no.exitCode, 0) << no.output;
    EXPECT_NE(no.output.find("bounce light       no"), std::string::npos) << no.output;
    // The memory estimate counts what bouncing adds only where light bounces.
    EXPECT_EQ(yes.output.find("bounce light 0 B"), std::string::npos) << yes.output;
    EXPECT_NE(no.output.find("bounce light 0 B"), std::string::npos) << no.output;
}

TEST_F(CliBounce, SdfMarchCannotBounce) {
    const RunResult r = runLuxel("render " + write("room.json", kRoom) +
                                 " --solver rc --march sdf --out " + path("x.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--march sdf cannot carry bounce light"), std::string::npos)
        << r.output;
}

}  // namespace
