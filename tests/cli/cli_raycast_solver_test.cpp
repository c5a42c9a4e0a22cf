// `luxel render --solver raycast`: the name of the voxel ray caster (the default without
// --solver), which luxel-view's --solver shares with ao and path; refused for 2D scenes.
#include <gtest/gtest.h>

#include <string>

#include "luxel/core/image_io.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliRayCastSolver : public luxel::test::CliFixture {};

const std::string kScenes = std::string(LUXEL_SOURCE_DIR) + "/scenes/";
const std::string kTerrain = kScenes + "voxel/terrain.json";

TEST_F(CliRayCastSolver, IsTheDefaultVoxelRendererByName) {
    RunResult r = runLuxel("render " + kTerrain +
                           " --solver raycast --backend cpu --size 32x18 "
                           "--out " +
                           path("named.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runLuxel("render " + kTerrain + " --backend cpu --size 32x18 --out " + path("default.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto named = luxel::readExr(path("named.exr")), plain = luxel::readExr(path("default.exr"));
    ASSERT_TRUE(named.ok() && plain.ok());
    ASSERT_EQ(named->size(), plain->size());
    int different = 0;
    for (std::size_t i = 0; i < named->size(); ++i)
        different += named->data()[i] != plain->data()[i];
    EXPECT_EQ(different, 0);
}

TEST_F(CliRayCastSolver, RefusedWhereItDoesNotApply) {
    const std::string out = " --out " + path("x.exr");
    expectError(
        "render " + kScenes + "2d/room.json --solver raycast" + out,
        "--solver raycast applies to voxel scenes; " + kScenes + "2d/room.json is a 2D scene");
    // The ray caster draws no random numbers.
    expectError("render " + kTerrain + " --solver raycast --seed 3" + out,
                "--seed applies to 2D scenes");
}

}  // namespace
