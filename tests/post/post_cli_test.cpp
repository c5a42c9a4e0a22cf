// `luxel render` post flags and `luxel upscale`: sizes, overrides and clear errors.
#include <gtest/gtest.h>

#include <string>

#include "luxel/core/image_io.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

namespace luxel {
namespace {

std::string cli() {
    return std::string(LUXEL_CLI_PATH) + " ";
}
std::string scene(const char* name) {
    return std::string(LUXEL_SOURCE_DIR) + "/scenes/" + name;
}

TEST(PostCli, InternalScaleRendersSmallerAndUpscalesToTheRequestedSize) {
    const test::TempDir tmp;
    const std::string out = tmp.path("post_cli.exr");
    const auto r = test::runCommand(cli() + "render " + scene("voxel/garden.json") +
                                    " --size 64x36 --internal-scale 0.5 --upscaler bilinear "
                                    "--bloom 0.2 --backend cpu --out " +
                                    out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("internal 32x18 (bilinear upscaler), bloom 0.20"), std::string::npos)
        << r.output;
    auto image = readImage(out);
    ASSERT_TRUE(image.ok()) << image.error().message();
    EXPECT_EQ(image->width(), 64);
    EXPECT_EQ(image->height(), 36);
}

TEST(PostCli, BadFlagsAreClearErrors) {
    const std::pair<std::string, const char*> cases[] = {
        {"render " + scene("voxel/garden.json") + " --upscaler fsr --out x.png",
         "--upscaler 'fsr' is not bilinear or edge"},
        {"render " + scene("2d/room.json") + " --bloom 0.2 --out x.png",
         "--bloom applies to voxel and octree scenes"},
        {"render " + scene("voxel/garden.json") + " --internal-scale 0.1 --out x.png",
         "--internal-scale"},
        {"upscale " + scene("2d/room.json"), "luxel upscale takes a voxel scene"},
    };
    for (const auto& [args, expected] : cases) {
        const auto r = test::runCommand(cli() + args);
        EXPECT_NE(r.exitCode, 0) << args;
        EXPECT_NE(r.output.find(expected), std::string::npos) << args << "\n" << r.output;
    }
}

TEST(PostCli, UpscaleReportPrintsATable) {
    const auto r = test::runCommand(cli() + "upscale " + scene("voxel/garden.json") +
                                    " --size 48x32 --frames 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* row : {"native", "bilinear", "edge", "temporal x2", "PSNR dB"}) {
        EXPECT_NE(r.output.find(row), std::string::npos) << row << "\n" << r.output;
    }
}

}  // namespace
}  // namespace luxel
