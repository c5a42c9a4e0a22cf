// CLI test: `luxel render --shadows METHOD` replaces the scene's render.shadows method (and turns
// shadows on), on the CPU and, where a Vulkan device is present, the GPU; unknown names and the
// GPU's missing exact method are refused with one clear line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "luxel/core/image_io.h"
#include "support/cli_fixture.h"

namespace luxel::test {
namespace {

class CliRenderShadows : public CliFixture {
  protected:
    // A wall on a floor under a wide sun: hard and soft shadows differ along the whole edge.
    std::string scene() {
        return write("wall.json", R"({"type": "voxel",
          "world": {"source": "empty", "size": [16, 10, 16], "chunk": 8, "shapes": [
            {"type": "box", "min": [0, 0, 0], "max": [16, 1, 16], "color": [150, 150, 150]},
            {"type": "box", "min": [3, 1, 7], "max": [13, 6, 8], "color": [200, 60, 60]}]},
          "camera": {"position": [8, 9, -3], "look_at": [8, 1, 8], "fov": 60, "size": [32, 18]},
          "sun": [0.2, 0.6, 0.6],
          "render": {"lighting": "physical", "shadows": false, "sun_radius": 8}})");
    }

    // Sum of |a - b| over the green channel of two EXR renders.
    double difference(const std::string& a, const std::string& b) {
        auto ia = readExr(path(a)), ib = readExr(path(b));
        EXPECT_TRUE(ia.ok() && ib.ok());
        if (!ia.ok() || !ib.ok()) return 0;
        double d = 0;
        for (int y = 0; y < ia->height(); ++y) {
            for (int x = 0; x < ia->width(); ++x) d += std::abs(ia->at(x, y, 1) - ib->at(x, y, 1));
        }
        return d;
    }
};

TEST_F(CliRenderShadows, FlagReplacesTheScenesMethod) {
    const std::string flags = " --backend cpu -q --out ";
    for (const char* m : {"hard", "sdf", "msm"}) {
        const RunResult r = runLuxel("render " + scene() + flags + path(std::string(m) + ".exr") +
                                     " --shadows " + m);
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    ASSERT_EQ(runLuxel("render " + scene() + flags + path("none.exr")).exitCode, 0);
    EXPECT_GT(difference("none.exr", "hard.exr"), 0.5) << "--shadows turns shadows on";
    EXPECT_GT(difference("hard.exr", "sdf.exr"), 0.05) << "a soft method changes the penumbra";
    EXPECT_GT(difference("sdf.exr", "msm.exr"), 0.0);
    expectError("render " + scene() + flags + path("x.exr") + " --shadows pcf",
                "--shadows 'pcf' is not hard, exact, msm, vsm, sdf, blend or flood");
}

TEST_F(CliRenderShadows, GpuRefusesExactAndMatchesTheCpu) {
    const RunResult probe =
        runLuxel("render " + scene() + " --backend gpu -q --shadows sdf --out " + path("g.exr"));
    if (probe.exitCode != 0) GTEST_SKIP() << "no Vulkan device: " << probe.output;
    ASSERT_EQ(
        runLuxel("render " + scene() + " --backend cpu -q --shadows sdf --out " + path("c.exr"))
            .exitCode,
        0);
    EXPECT_LT(difference("g.exr", "c.exr"), 0.05 * 32 * 18 * 0.01);
    expectError("render " + scene() + " --backend gpu -q --shadows exact --out " + path("x.exr"),
                "'exact'");
}

}  // namespace
}  // namespace luxel::test
