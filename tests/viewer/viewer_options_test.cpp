// luxel-view's command line.
#include <gtest/gtest.h>

#include <cmath>

#include "viewer_options.h"

namespace luxel::viewer {
namespace {

TEST(ViewerOptions, ParsesSizesAndChoices) {
    auto parsed = parseViewerOptions(
        {"scene.json", "--size",       "640x480", "--internal-size", "160x120",      "--backend",
         "cpu",        "--solver",     "rc",      "--merge",         "bilinear-fix", "--record",
         "5",          "--record-dir", "out",     "--script",        "s.txt",        "--frame",
         "3",          "--target-fps", "30"});
    ASSERT_TRUE(parsed) << parsed.error().message();
    const ViewerOptions& o = parsed->options;
    EXPECT_EQ(o.scene, "scene.json");
    EXPECT_EQ(o.windowWidth, 640);
    EXPECT_EQ(o.windowHeight, 480);
    EXPECT_EQ(o.internalWidth, 160);
    EXPECT_EQ(o.internalHeight, 120);
    EXPECT_EQ(o.backend, gpu::Backend::Cpu);
    EXPECT_EQ(o.solver, gi2d::Solver2D::Rc);
    EXPECT_EQ(o.merge, gi2d::RcMerge::BilinearFix);
    EXPECT_EQ(o.recordFrames, 5);
    EXPECT_EQ(o.recordDir, "out");
    EXPECT_EQ(o.script, "s.txt");
    EXPECT_EQ(o.voxFrame, 3);
    EXPECT_EQ(o.targetFps, 30.0);
    // Without them: the scene's frame, and an adaptive size at 15 frames per second.
    auto plain = parseViewerOptions({"scene.json"});
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->options.voxFrame, -1);
    EXPECT_EQ(plain->options.targetFps, 15.0);
}

TEST(ViewerOptions, RejectsBadValuesWithTheOptionName) {
    struct Case {
        std::vector<std::string> args;
        const char* needle;
    };
    const Case cases[] = {
        {{}, "scene"},
        {{"s.json", "--frame", "-2"}, "--frame"},
        {{"s.json", "--target-fps", "-1"}, "--target-fps"},
        {{"s.json", "--size", "640"}, "--size '640' is not WIDTHxHEIGHT"},
        {{"s.json", "--internal-size", "0x10"},
         "--internal-size '0x10': each side must be in 1..65536"},
        {{"s.json", "--backend", "metal"}, "--backend 'metal' is not one of: auto, cpu, gpu"},
        {{"s.json", "--solver", "pt"}, "--solver 'pt' is not one of: reference, hrc, rc"},
        {{"s.json", "--merge", "nearest"}, "--merge 'nearest' is not one of"},
        {{"s.json", "--internal-scale", "0"}, "--internal-scale"},
        {{"s.json", "--internal-scale", "nan"}, "--internal-scale: 'nan' is not a finite number"},
        {{"s.json", "--exposure", "nan"}, "--exposure: 'nan' is not a finite number in [-64, 64]"},
        {{"s.json", "--exposure", "inf"}, "--exposure: 'inf'"},
        {{"s.json", "--threads", "-5"}, "--threads"},
        {{"s.json", "--solver", "raycaster"}, "(voxel scenes: raycast, ao, path, rc)"},
        {{"s.json", "--spp", "0"}, "--spp"},
        {{"s.json", "--max-bounces", "-1"}, "--max-bounces"},
        {{"s.json", "--ao-rays", "0"}, "--ao-rays"},
        {{"s.json", "--ao-radius", "0"}, "--ao-radius must be > 0 voxels"},
        {{"s.json", "--ao-radius", "-3"}, "--ao-radius must be > 0 voxels"},
    };
    for (const Case& c : cases) {
        auto parsed = parseViewerOptions(c.args);
        ASSERT_FALSE(parsed) << c.needle;
        EXPECT_NE(parsed.error().message().find(c.needle), std::string::npos)
            << parsed.error().message();
    }
    auto help = parseViewerOptions({"--help"});
    ASSERT_TRUE(help);
    EXPECT_TRUE(help->helpRequested);
    EXPECT_NE(help->helpText.find("--script"), std::string::npos);
}

TEST(ViewerOptions, VoxelSolversTakeTheNamesOfLuxelRender) {
    auto parsed =
        parseViewerOptions({"world.json", "--solver", "path", "--spp", "64", "--max-bounces", "2",
                            "--seed", "9", "--ao-rays", "32", "--ao-radius", "12.5"});
    ASSERT_TRUE(parsed) << parsed.error().message();
    const ViewerOptions& o = parsed->options;
    ASSERT_TRUE(o.voxelSolver.has_value());
    EXPECT_EQ(*o.voxelSolver, VoxelSolver::PathTrace);
    EXPECT_FALSE(o.solver2DGiven);
    EXPECT_EQ(o.path.samplesPerPixel, 64);
    EXPECT_EQ(o.path.maxBounces, 2);
    EXPECT_EQ(o.path.seed, 9u);
    EXPECT_EQ(o.ao.seed, 9u);
    EXPECT_EQ(o.ao.rays, 32);
    EXPECT_EQ(o.ao.radius, 12.5);
    EXPECT_EQ(o.voxelFlagsGiven.size(), 5u);
    for (const char* name : {"ao", "raycast"}) {
        auto other = parseViewerOptions({"world.json", "--solver", name});
        ASSERT_TRUE(other) << name;
        ASSERT_TRUE(other->options.voxelSolver.has_value());
        EXPECT_STREQ(voxelSolverName(*other->options.voxelSolver), name);
    }
    // Defaults: no voxel solver named (the ray caster starts), the path tracer stops at 1024
    // samples, sky visibility sees the whole sky; a 2D name is remembered as given.
    auto plain = parseViewerOptions({"world.json"});
    ASSERT_TRUE(plain);
    EXPECT_FALSE(plain->options.voxelSolver.has_value());
    EXPECT_FALSE(plain->options.solver2DGiven);
    EXPECT_EQ(plain->options.path.samplesPerPixel, kDefaultViewerPathSamples);
    EXPECT_TRUE(std::isinf(plain->options.ao.radius));
    EXPECT_TRUE(plain->options.voxelFlagsGiven.empty());
    auto wholeSky = parseViewerOptions({"world.json", "--ao-radius", "inf"});
    ASSERT_TRUE(wholeSky) << wholeSky.error().message();
    EXPECT_TRUE(std::isinf(wholeSky->options.ao.radius));
    EXPECT_FALSE(parseViewerOptions({"world.json", "--ao-radius", "nan"}));
    auto twoD = parseViewerOptions({"room.json", "--solver", "reference"});
    ASSERT_TRUE(twoD);
    EXPECT_TRUE(twoD->options.solver2DGiven);
    EXPECT_FALSE(twoD->options.voxelSolver.has_value());
}

}  // namespace
}  // namespace luxel::viewer
