// `luxel compare-solvers` on a voxel scene: the path tracer as the reference, sky visibility and
// the ray caster measured against it, a labelled grid, and the 2D-only options refused.
#include <gtest/gtest.h>

#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_metadata.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliCompareVoxel : public luxel::test::CliFixture {};

const std::string kCottage = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json";

TEST_F(CliCompareVoxel, MeasuresSkyVisibilityAndTheRayCasterAgainstThePathTracer) {
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

    luxel::ImageMetadata metadata;
    auto grid = luxel::readPng(path("grid.png"), luxel::PngEncoding::Srgb, &metadata);
    ASSERT_TRUE(grid.ok()) << grid.error().message();
    EXPECT_EQ(grid->width(), 3 * 48 + 2 * 4) << "three panels";
    EXPECT_NE(luxel::findMetadata(metadata, "luxel.panel2.ao"), nullptr);
}

TEST_F(CliCompareVoxel, RefusesTheTwoDimensionalOptions) {
    for (const char* option :
         {"--rays 16", "--move 4,0", "--error-image e.png", "--reference r.exr"}) {
        expectError("compare-solvers " + kCottage + " " + option, "applies to 2D scenes");
    }
}

}  // namespace
