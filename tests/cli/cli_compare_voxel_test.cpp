// `luxel compare-solvers` on a voxel scene: the path tracer as the reference, sky visibility and
// the ray caster measured against it, a labelled grid, a reused path-traced reference, and the
// 2D-only options refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_metadata.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliCompareVoxel : public luxel::test::CliFixture {};

const std::string kCottage = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json";
const std::string kThinWalls = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/thin-walls.json";

// The leak/mean column (percent) of a solver's row: the 7th number after its label.
double leakPercent(const std::string& output, const std::string& solver) {
    const auto row = output.find("\n" + solver + " ");
    if (row == std::string::npos) return std::nan("");
    double v[7] = {};
    if (std::sscanf(output.c_str() + row + solver.size() + 2, "%lf %lf %lf %lf%% %lf%% %lf%%",
                    &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) != 6) {
        return std::nan("");
    }
    return v[5];
}

TEST_F(CliCompareVoxel, MeasuresSkyVisibilityCascadesAndTheRayCasterAgainstThePathTracer) {
    const RunResult r = runLuxel("compare-solvers " + kCottage + " --size 48x27 --spp 8 --grid " +
                                 path("grid.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("reference: path tracer, 8 samples/pixel"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("low-freq/mean"), std::string::npos) << r.output;
    // The reference against itself is exact; the others are not.
    EXPECT_NE(r.output.find("path"), std::string::npos) << r.output;
    const auto aoRow = r.output.find("\nao ");
    const auto casterRow = r.output.find("\nray-caster ");
    ASSERT_NE(aoRow, std::string::npos) << r.output;
    ASSERT_NE(casterRow, std::string::npos) << r.output;
    double ms = 0, relL1 = 0;
    ASSERT_EQ(std::sscanf(r.output.c_str() + aoRow + 4, "%lf %lf", &ms, &relL1), 2) << r.output;
    EXPECT_GT(relL1, 0.0);
    EXPECT_LT(relL1, 0.2);  // the same light, short of its bounces and glow
    const auto rcRow = r.output.find("\nrc ");
    ASSERT_NE(rcRow, std::string::npos) << r.output;
    ASSERT_EQ(std::sscanf(r.output.c_str() + rcRow + 4, "%lf %lf", &ms, &relL1), 2) << r.output;
    EXPECT_GT(relL1, 0.0);
    EXPECT_LT(relL1, 0.2);  // the same light and its bounces, without noise

    luxel::ImageMetadata metadata;
    auto grid = luxel::readPng(path("grid.png"), luxel::PngEncoding::Srgb, &metadata);
    ASSERT_TRUE(grid.ok()) << grid.error().message();
    EXPECT_EQ(grid->width(), 4 * 48 + 3 * 4) << "four panels";
    EXPECT_NE(luxel::findMetadata(metadata, "luxel.panel3.rc"), nullptr);
    EXPECT_NE(luxel::findMetadata(metadata, "luxel.panel2.ao"), nullptr);
}

TEST_F(CliCompareVoxel, MeasuresLightLeakedIntoTheSealedRoomOfThinWalls) {
    const RunResult r = runLuxel("compare-solvers " + kThinWalls +
                                 " --size 64x36 --spp 16 --grid " + path("grid.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("leak/mean"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("dark region: "), std::string::npos) << r.output;
    const double pathLeak = leakPercent(r.output, "path");
    const double ao = leakPercent(r.output, "ao");
    const double caster = leakPercent(r.output, "ray-caster");
    std::printf("leak, %% of the reference mean: path %.2f, ao %.2f, ray caster %.2f\n", pathLeak,
                ao, caster);
    EXPECT_EQ(pathLeak, 0.0) << r.output;
    // Sky visibility traces exact rays: the sun and the sky stay outside. It misses the lamp's
    // second and later bounces, so it can be darker than the reference there, by at most the dark
    // region's own light (below 10% of the mean); brighter only by noise.
    EXPECT_GT(ao, -10.0) << r.output;
    EXPECT_LT(ao, 1.0) << r.output;
    // The scene's ray caster traces its sky ambient (render.sky_ambient_rays): its rays find no
    // sky in the sealed room, which holds the lamp's direct light alone, so it leaks no more than
    // sky visibility. (With the constant share, --sky-ambient-rays 0, the room got it all:
    // CliSkyAmbient.RaysDarkenTheSealedRoom.)
    EXPECT_GT(caster, -10.0) << r.output;
    EXPECT_LT(caster, 1.0) << r.output;

    luxel::ImageMetadata metadata;
    auto grid = luxel::readPng(path("grid.png"), luxel::PngEncoding::Srgb, &metadata);
    ASSERT_TRUE(grid.ok()) << grid.error().message();
    const std::string* aoLeak = luxel::findMetadata(metadata, "luxel.leak.ao");
    ASSERT_NE(aoLeak, nullptr);
    EXPECT_NEAR(std::stod(*aoLeak) * 100.0, ao, 0.01);
    EXPECT_NE(luxel::findMetadata(metadata, "luxel.dark_blocks"), nullptr);
}

TEST_F(CliCompareVoxel, RefusesTheTwoDimensionalOptions) {
    for (const char* option : {"--rays 16", "--move 4,0", "--error-image e.png"}) {
        expectError("compare-solvers " + kCottage + " " + option, "applies to 2D scenes");
    }
    expectError(
        "compare-solvers " + std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/room.json --samples 4",
        "--samples applies to voxel scenes");
}

// --reference: a path-traced EXR of the scene at the size compared stands in for the reference;
// any other is refused with what is wrong with it.
TEST_F(CliCompareVoxel, ReusesAPathTracedReference) {
    const std::string ref = path("ref.exr"), rc = path("rc.exr");
    ASSERT_EQ(runLuxel("render " + kCottage + " --solver path --spp 8 --size 48x27 --out " + ref)
                  .exitCode,
              0);
    const RunResult r =
        runLuxel("compare-solvers " + kCottage + " --size 48x27 --reference " + ref);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("reference: path tracer, 8 samples/pixel, from " + ref),
              std::string::npos)
        << r.output;
    const auto pathRow = r.output.find("\npath ");
    ASSERT_NE(pathRow, std::string::npos) << r.output;
    double ms = 0, relL1 = -1;
    ASSERT_EQ(std::sscanf(r.output.c_str() + pathRow + 6, "%lf %lf", &ms, &relL1), 2) << r.output;
    EXPECT_EQ(relL1, 0.0);
    EXPECT_NE(r.output.find("\nrc "), std::string::npos) << r.output;
    // --samples: the other solvers' pictures take that many rays a pixel.
    const RunResult sampled =
        runLuxel("compare-solvers " + kCottage + " --size 48x27 --samples 4 --reference " + ref);
    ASSERT_EQ(sampled.exitCode, 0) << sampled.output;
    EXPECT_NE(sampled.output.find("the other solvers: 4 samples/pixel"), std::string::npos)
        << sampled.output;

    const std::string compare = "compare-solvers " + kCottage + " ";
    expectError(compare + "--size 32x18 --reference " + ref, "is 48x27 but");
    ASSERT_EQ(runLuxel("render " + kCottage + " --solver rc --size 48x27 --out " + rc).exitCode, 0);
    expectError(compare + "--size 48x27 --reference " + rc, "rendered by the rc solver");
    expectError(compare + "--reference r.png", "must be a radiance EXR");
    expectError(compare + "--reference " + path("missing.exr"), "missing.exr");
    expectError(compare + "--size 48x27 --reference " + ref + " --grid g.png",
                "does not apply to --grid");
    expectError(compare + "--reference " + ref + " --sun-sweep 2", "does not apply to --sun-sweep");
}

}  // namespace
