// `luxel compare-solvers VOXEL.json --sun-sweep N`: every voxel solver under a turning sun and
// its flicker against the reference's change; `luxel render --sun-yaw` that turns the sun; and
// the bad values both refuse.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_metadata.h"
#include "luxel/core/metrics.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliSunSweep : public luxel::test::CliFixture {};

const std::string kCottage = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json";
const std::string kTwoD = std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/fog.json";

// The flicker/mean column (percent) of a solver's row.
double flickerPercent(const std::string& output, const std::string& solver) {
    const auto row = output.find("\n" + solver + " ");
    double ms = 0, relL1 = 0, flicker = 0;
    if (row == std::string::npos || std::sscanf(output.c_str() + row + solver.size() + 2,
                                                "%lf %lf %lf%%", &ms, &relL1, &flicker) != 3) {
        return std::nan("");
    }
    return flicker;
}

TEST_F(CliSunSweep, MeasuresEachSolversFlickerAgainstTheReference) {
    const RunResult r =
        runLuxel("compare-solvers " + kCottage +
                 " --size 48x27 --spp 8 --sun-sweep 3 --sun-step 5 --grid " + path("grid.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("3 sun directions 5 degrees apart"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("flicker/mean"), std::string::npos) << r.output;
    const double pathFlicker = flickerPercent(r.output, "path");
    const double ao = flickerPercent(r.output, "ao");
    const double caster = flickerPercent(r.output, "ray-caster");
    std::printf("flicker, %% of the mean: path %.4f, ao %.4f, ray caster %.4f\n", pathFlicker, ao,
                caster);
    EXPECT_EQ(pathFlicker, 0.0) << r.output;
    // The others differ from the reference (its noise, their missing bounces), a little.
    EXPECT_GT(ao, 0.0) << r.output;
    EXPECT_LT(ao, 5.0) << r.output;
    EXPECT_GT(caster, 0.0) << r.output;
    EXPECT_LT(caster, 5.0) << r.output;
    // The reference with another seed flickers by its noise alone.
    const double seed2 = flickerPercent(r.output, "path-seed2");
    EXPECT_GT(seed2, 0.0) << r.output;
    EXPECT_LT(seed2, 5.0) << r.output;

    luxel::ImageMetadata metadata;
    auto grid = luxel::readPng(path("grid.png"), luxel::PngEncoding::Srgb, &metadata);
    ASSERT_TRUE(grid.ok()) << grid.error().message();
    EXPECT_EQ(grid->width(), 5 * 48 + 4 * 4) << "five panels";
    EXPECT_NE(luxel::findMetadata(metadata, "luxel.flicker.rc"), nullptr);
    const std::string* frames = luxel::findMetadata(metadata, "luxel.sun_sweep.frames");
    ASSERT_NE(frames, nullptr);
    EXPECT_EQ(*frames, "3");
    EXPECT_NE(luxel::findMetadata(metadata, "luxel.flicker.ray-caster"), nullptr);
}

TEST_F(CliSunSweep, RefusesBadSweeps) {
    expectError("compare-solvers " + kCottage + " --sun-sweep 1", "--sun-sweep");
    expectError("compare-solvers " + kCottage + " --sun-sweep 0", "--sun-sweep");
    expectError("compare-solvers " + kCottage + " --sun-sweep many", "--sun-sweep");
    expectError("compare-solvers " + kCottage + " --sun-sweep 100000", "--sun-sweep");
    expectError("compare-solvers " + kCottage + " --sun-sweep 3 --sun-step 0", "must not be 0");
    expectError("compare-solvers " + kCottage + " --sun-sweep 3 --sun-step nan", "--sun-step");
    expectError("compare-solvers " + kCottage + " --sun-sweep 3 --sun-step 120", "--sun-step");
    expectError("compare-solvers " + kCottage + " --sun-step 2", "applies to --sun-sweep");
    expectError("compare-solvers " + kTwoD + " --sun-sweep 3", "applies to voxel scenes");
}

TEST_F(CliSunSweep, RenderTurnsTheSunAboutTheVertical) {
    // Half a turn is a different image; a full turn the same one, to float rounding.
    for (const char* yaw : {"0", "180", "360"}) {
        const RunResult r = runLuxel("render " + kCottage + " --size 64x36 --quiet --sun-yaw " +
                                     yaw + " --out " + path(std::string("yaw") + yaw + ".exr"));
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    auto base = luxel::readExr(path("yaw0.exr"));
    auto half = luxel::readExr(path("yaw180.exr"));
    auto full = luxel::readExr(path("yaw360.exr"));
    ASSERT_TRUE(base.ok() && half.ok() && full.ok());
    EXPECT_GT(luxel::compareImages(*half, *base)->relativeL1, 0.01);
    EXPECT_LT(luxel::compareImages(*full, *base)->relativeL1, 1e-3);
    expectError("render " + kCottage + " --sun-yaw nan --out " + path("x.exr"), "--sun-yaw");
    expectError("render " + kTwoD + " --sun-yaw 10 --out " + path("x.exr"),
                "--sun-yaw applies to voxel scenes");
}

}  // namespace
