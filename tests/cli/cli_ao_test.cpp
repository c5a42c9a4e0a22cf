// `luxel render --solver ao` end to end: a shipped voxel scene shaded with sky visibility at a
// small size (image, provenance, summary), and the refusals: its options without it, bad ray
// counts and radii, ao on a 2D scene, the ray caster's and the path tracer's flags with it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_metadata.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliAo : public luxel::test::CliFixture {};

const std::string kScenes = std::string(LUXEL_SOURCE_DIR) + "/scenes/";
const std::string kTerrain = kScenes + "voxel/terrain.json";

TEST_F(CliAo, ShadesAVoxelSceneWithSkyVisibility) {
    const RunResult r = runLuxel("render " + kTerrain +
                                 " --solver ao --ao-rays 4 --ao-radius 8 --seed 3 --size 32x18 "
                                 "--out " +
                                 path("a.exr") + " --png " + path("a.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("sky visibility"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("sky visibility: 4 rays per point, radius 8 voxels, seed 3"),
              std::string::npos)
        << r.output;
    luxel::ImageMetadata metadata;
    auto exr = luxel::readExr(path("a.exr"), &metadata);
    ASSERT_TRUE(exr.ok()) << exr.error().message();
    EXPECT_EQ(exr->width(), 32);
    EXPECT_EQ(exr->height(), 18);
    double sum = 0.0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 32; ++x) sum += exr->at(x, y, 1);
    EXPECT_TRUE(std::isfinite(sum));
    EXPECT_GT(sum, 0.0);
    const std::string* solver = luxel::findMetadata(metadata, "luxel.solver");
    ASSERT_NE(solver, nullptr);
    EXPECT_EQ(*solver, "ao");
    const std::string* rays = luxel::findMetadata(metadata, "luxel.ao.rays");
    ASSERT_NE(rays, nullptr);
    EXPECT_EQ(*rays, "4");
    EXPECT_TRUE(luxel::readPng(path("a.png")).ok());
}

TEST_F(CliAo, RefusesAoWhereItDoesNotApply) {
    const std::string out = " --out " + path("x.exr");
    expectError("render " + kTerrain + " --ao-rays 4" + out, "--ao-rays applies to --solver ao");
    expectError("render " + kTerrain + " --solver path --ao-radius 2" + out,
                "--ao-radius applies to --solver ao");
    expectError("render " + kScenes + "2d/room.json --solver ao" + out,
                "--solver ao applies to voxel scenes; " + kScenes + "2d/room.json is a 2D scene");
    expectError("render " + kTerrain + " --solver ao --spp 4" + out,
                "--spp applies to --solver path");
    expectError("render " + kTerrain + " --solver ao --lighting classic" + out,
                "apply to the ray caster; --solver ao takes --ao-rays, --ao-radius and --samples");
    expectError("render " + kTerrain + " --solver ao --backend gpu" + out,
                "--solver ao runs on the CPU");
    for (const char* rays : {"0", "-3", "1e9", "nan"}) {
        const RunResult r = runLuxel("render " + kTerrain + " --solver ao --ao-rays " + rays + out);
        EXPECT_EQ(r.exitCode, 1) << rays << ": " << r.output;
        EXPECT_NE(r.output.find("--ao-rays"), std::string::npos) << r.output;
    }
    for (const char* radius : {"0", "-1", "nan", "abc"}) {
        const RunResult r =
            runLuxel("render " + kTerrain + " --solver ao --ao-radius " + radius + out);
        EXPECT_EQ(r.exitCode, 1) << radius << ": " << r.output;
        EXPECT_NE(r.output.find("--ao-radius"), std::string::npos) << r.output;
    }
}

}  // namespace
