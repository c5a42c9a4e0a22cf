// `luxel render --no-emitter-light` and `--emitter-rays N`: the ray caster's light from emissive
// voxels (docs/algorithms/voxel-surfaces.md) turned off or given more shadow rays from the
// command line; the other solvers refuse both.
#include <gtest/gtest.h>

#include <string>

#include "cli/thin_walls_cli.h"

namespace {

using luxel::test::meanOf;
using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliEmitterLight : public luxel::test::ThinWallsCli {};

int pixelsThatDiffer(const luxel::Image& a, const luxel::Image& b) {
    int different = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        different += a.data()[i] != b.data()[i];
    return different;
}

TEST_F(CliEmitterLight, TheLampLightsTheRoomUnlessTurnedOff) {
    const luxel::Image lit = render("lit.exr", "");
    const luxel::Image dark = render("dark.exr", "--no-emitter-light");
    ASSERT_EQ(lit.size(), dark.size());
    ASSERT_GT(lit.size(), 0u);
    // The lamp's light only adds: every value at least the unlit one, and the room brighter.
    int darker = 0;
    for (std::size_t i = 0; i < lit.size(); ++i) darker += lit.data()[i] < dark.data()[i] - 1e-6f;
    EXPECT_EQ(darker, 0);
    EXPECT_GT(meanOf(lit), meanOf(dark) * 1.001);
    EXPECT_GT(pixelsThatDiffer(lit, dark), int(lit.size() / 20));
}

TEST_F(CliEmitterLight, MoreShadowRaysChangeThePenumbraeNotTheLight) {
    const luxel::Image four = render("four.exr", "");
    const luxel::Image sixteen = render("sixteen.exr", "--emitter-rays 16");
    ASSERT_EQ(four.size(), sixteen.size());
    ASSERT_GT(four.size(), 0u);
    EXPECT_GT(pixelsThatDiffer(four, sixteen), 0);
    EXPECT_NEAR(meanOf(sixteen), meanOf(four), 0.02 * meanOf(four));
}

TEST_F(CliEmitterLight, BadCountsAndOtherSolversAreRefused) {
    const std::string out = " --out " + path("x.exr");
    expectError("render " + kThinWalls + " --emitter-rays 0" + out, "--emitter-rays");
    expectError("render " + kThinWalls + " --emitter-rays 65" + out, "--emitter-rays");
    expectError("render " + kThinWalls + " --solver path --no-emitter-light" + out,
                "apply to the ray caster");
    expectError("render " + kThinWalls + " --solver rc --emitter-rays 8" + out,
                "apply to the ray caster");
}

// `luxel info` counts what the light from emissive voxels builds: thin-walls' lamp is one voxel
// on the floor, so five of its faces are open.
TEST_F(CliEmitterLight, InfoCountsTheLampFacesAndTheirLists) {
    const RunResult r = runLuxel("info " + kThinWalls);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(
                  "lamp light         5 open emissive faces in 5 rectangles, 4 shadow rays each"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("lamp lists"), std::string::npos) << r.output;
}

}  // namespace
