// CLI test: luxel shadows prints one row per method with finite numbers, writes V images, and
// refuses unknown methods and non-voxel scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "support/cli_fixture.h"

namespace luxel::test {
namespace {

class CliShadows : public CliFixture {
  protected:
    std::string tinyScene() {
        return write("tiny.json", R"({"type": "voxel",
          "world": {"source": "empty", "size": [16, 10, 16], "chunk": 8, "shapes": [
            {"type": "box", "min": [0, 0, 0], "max": [16, 1, 16], "color": [120, 120, 120]},
            {"type": "box", "min": [5, 1, 7], "max": [6, 6, 8], "color": [200, 50, 50]},
            {"type": "box", "min": [5, 5, 7], "max": [12, 6, 8], "color": [200, 50, 50]}]},
          "camera": {"position": [8, 9, -3], "look_at": [8, 1, 8], "fov": 60, "size": [32, 18]},
          "sun": [0.4, 0.6, 0.5],
          "render": {"shadows": {"method": "blend", "map_size": 64, "blend_near": 8,
                                 "blend_far": 12}, "sun_radius": 3}})");
    }
};

TEST_F(CliShadows, PrintsAFiniteRowPerMethodAndWritesImages) {
    const RunResult r = runLuxel("shadows " + tinyScene() +
                                 " --size 32x18 --samples 16 --frames 2 "
                                 "--sun-step 2 --out-dir " +
                                 path("out"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const char* methods[] = {
        "hard",      "msm",          "msm16",          "vsm",
        "sdf",       "sdf-centres",  "blend",          "blend-msm-near",
        "blend-min", "msm-penumbra", "blend-penumbra", "blend-msm-near-penumbra",
        "flood"};
    std::istringstream lines(r.output);
    std::string line;
    int rows = 0;
    while (std::getline(lines, line)) {
        std::istringstream fields(line);
        std::string name;
        fields >> name;
        for (const char* m : methods) {
            if (name != m) continue;
            ++rows;
            double v;
            int count = 0;
            while (fields >> v) {
                EXPECT_TRUE(std::isfinite(v)) << line;
                // The penumbra bias (column 1) and flicker (column 6) may be negative.
                EXPECT_GE(v, count == 1 || count == 6 ? -1.0 : 0.0) << line;
                if (count == 1) {
                    EXPECT_LE(v, 1.0) << line;
                }
                ++count;
            }
            EXPECT_EQ(count, 8) << line;
        }
    }
    EXPECT_EQ(rows, 13) << r.output;
    EXPECT_NE(r.output.find("exact (truth)"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(path("out") + "/tiny-exact.png"));
    EXPECT_TRUE(std::filesystem::exists(path("out") + "/tiny-blend.png"));
}

TEST_F(CliShadows, MarkdownAndMethodSubset) {
    const RunResult r = runLuxel("shadows " + tinyScene() +
                                 " --samples 4 --size 16x9 --methods sdf,msm --markdown");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("| sdf "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("| msm "), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("| vsm "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("| pen. bias |"), std::string::npos) << r.output;
}

TEST_F(CliShadows, SunRadiusAndBlendBandOverrideTheScene) {
    const RunResult r = runLuxel("shadows " + tinyScene() +
                                 " --samples 4 --size 16x9 --methods blend --sun-radius 1 "
                                 "--blend-band 0,20");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("blend band 0..20"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("sun radius 1.00 deg"), std::string::npos) << r.output;
    const RunResult bad = runLuxel("shadows " + tinyScene() + " --size 16x9 --sun-radius 30");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.output.find("sun-radius"), std::string::npos) << bad.output;
}

TEST_F(CliShadows, RefusesBadInput) {
    expectError("shadows " + tinyScene() + " --size 16x9 --methods pcss", "unknown method 'pcss'");
    const std::string twoD = std::string(LUXEL_SOURCE_DIR) + "/scenes/" + "two_lights.json";
    if (std::filesystem::exists(twoD)) expectError("shadows " + twoD, "voxel scenes");
}

}  // namespace
}  // namespace luxel::test
