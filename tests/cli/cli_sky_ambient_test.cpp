// `luxel render --sky-ambient-rays N`: the ray caster's sky ambient with occlusion
// (docs/algorithms/voxel-surfaces.md) from the command line. On thin-walls the sealed room loses
// the sky light the constant share gave it; the other solvers refuse the flag.
#include <gtest/gtest.h>

#include <string>

#include "cli/thin_walls_cli.h"

namespace {

using luxel::test::meanOf;
using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliSkyAmbient : public luxel::test::ThinWallsCli {};

TEST_F(CliSkyAmbient, RaysDarkenTheSealedRoom) {
    const luxel::Image constant = render("constant.exr", "--sky-ambient-rays 0");
    const luxel::Image traced = render("traced.exr", "--sky-ambient-rays 8");
    ASSERT_EQ(constant.size(), traced.size());
    ASSERT_GT(constant.size(), 0u);
    // Inside, only the lamp lights the room: the traced picture holds a small part of the light
    // the constant share gave it, and no value exceeds the constant share's.
    EXPECT_LT(meanOf(traced), 0.2 * meanOf(constant));
    int brighter = 0;
    for (std::size_t i = 0; i < traced.size(); ++i) {
        brighter += traced.data()[i] > constant.data()[i] + 1e-6f;
    }
    EXPECT_EQ(brighter, 0);
}

TEST_F(CliSkyAmbient, BadCountsAndOtherSolversAreRefused) {
    const std::string out = " --out " + path("x.exr");
    expectError("render " + kThinWalls + " --sky-ambient-rays -1" + out, "--sky-ambient-rays");
    expectError("render " + kThinWalls + " --sky-ambient-rays 257" + out, "--sky-ambient-rays");
    expectError("render " + kThinWalls + " --solver path --sky-ambient-rays 8" + out,
                "apply to the ray caster");
}

}  // namespace
