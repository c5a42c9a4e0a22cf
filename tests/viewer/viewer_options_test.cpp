// luxel-view's command line.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace luxel::viewer
