// The voxel scenes' sky from the command line: `luxel info` names the model, a render of the
// shipped Preetham scene shows its sky (deep blue high up, whiter towards the horizon), and a bad
// sky is refused naming the field (docs/scene-format-voxel.md, "Sky models").
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>

#include "luxel/core/image_io.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

const std::string kEvening = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain-evening.json";
const std::string kTerrain = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json";

class CliSky : public luxel::test::CliFixture {};

TEST_F(CliSky, InfoNamesTheModel) {
    const std::pair<std::string, std::string> cases[] = {
        {kEvening, "sky                Preetham clear sky, turbidity 3, zenith luminance 0.5"},
        {kTerrain, "sky                gradient, top (0.18, 0.36, 0.8), horizon (0.75, 0.85, 1)"}};
    for (const auto& [scene, line] : cases) {
        const RunResult r = runLuxel("info " + scene);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(line), std::string::npos) << r.output;
    }
}

// The top row of the picture looks about 30° up, the row at 40% of the height about 4°: under a
// sun 16° up the Preetham sky is blue there (blue / red 1.92) and warm near the horizon (0.71);
// the shipped terrain's gradient sky would read about 2.0 and 1.4.
TEST_F(CliSky, ThePreethamSkyIsBlueAboveAndWhiterBelow) {
    const RunResult r =
        runLuxel("render " + kEvening + " --backend cpu --size 64x36 --out " + path("evening.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto image = luxel::readExr(path("evening.exr"));
    ASSERT_TRUE(image.ok()) << image.error().message();
    const auto blueOverRed = [&](int y) {
        double red = 0.0, blue = 0.0;
        for (int x = 0; x < image->width(); ++x) {
            red += image->at(x, y, 0);
            blue += image->at(x, y, 2);
        }
        return blue / red;
    };
    const double high = blueOverRed(0), low = blueOverRed(image->height() * 2 / 5);
    std::printf("blue / red: %.3f in the top row, %.3f near the horizon\n", high, low);
    EXPECT_GT(high, 1.6);
    EXPECT_LT(low, 0.9);
}

TEST_F(CliSky, ABadSkyIsRefusedNamingTheField) {
    const std::string scene = write("bad-sky.json", R"({"type": "voxel",
        "world": {"source": "empty", "size": [4, 4, 4]},
        "camera": {"position": [2, 2, -4]},
        "sky": {"model": "preetham", "turbidity": 12}})");
    expectError("info " + scene, "bad-sky.json:4:");
    expectError("info " + scene, "sky.turbidity: must be in 2..10");
}

}  // namespace
