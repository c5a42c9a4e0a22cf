// `luxel render --solver rc` on a voxel scene end to end: the cottage with radiance cascades at a
// small size (image, provenance, summary), the lighting passes on the GPU, and the refusals:
// --rc-spacing without it or on a 2D scene, bad spacings and bounce counts, the ray caster's
// flags, an octree scene.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_metadata.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliRcVoxel : public luxel::test::CliFixture {};

const std::string kScenes = std::string(LUXEL_SOURCE_DIR) + "/scenes/";
const std::string kCottage = kScenes + "voxel/cottage.json";

TEST_F(CliRcVoxel, LightsAVoxelSceneWithRadianceCascades) {
    const RunResult r = runLuxel("render " + kCottage +
                                 " --solver rc --rc-spacing 4 --bounces 3 --size 48x27 --out " +
                                 path("c.exr") + " --png " + path("c.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("radiance cascades: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("levels from spacing 4"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("3 bounces"), std::string::npos) << r.output;
    luxel::ImageMetadata metadata;
    auto exr = luxel::readExr(path("c.exr"), &metadata);
    ASSERT_TRUE(exr.ok()) << exr.error().message();
    EXPECT_EQ(exr->width(), 48);
    EXPECT_EQ(exr->height(), 27);
    double sum = 0.0;
    for (int y = 0; y < 27; ++y)
        for (int x = 0; x < 48; ++x) sum += exr->at(x, y, 1);
    EXPECT_TRUE(std::isfinite(sum));
    EXPECT_GT(sum, 0.0);
    for (const auto& [key, value] : {std::pair<const char*, const char*>{"luxel.solver", "rc"},
                                     {"luxel.rc.spacing", "4"},
                                     {"luxel.rc.bounces", "3"}}) {
        const std::string* found = luxel::findMetadata(metadata, key);
        ASSERT_NE(found, nullptr) << key;
        EXPECT_EQ(*found, value) << key;
    }
    EXPECT_TRUE(luxel::readPng(path("c.png")).ok());
}

// --samples takes stratified rays inside each pixel for the cascades' picture and sky
// visibility as for the ray caster (the path tracer keeps --spp): recorded, and the picture
// changes where edges cross pixels.
TEST_F(CliRcVoxel, SamplesAntialiasThePictures) {
    for (const char* solver : {"rc", "ao"}) {
        const std::string base = "render " + kCottage + " --solver " + solver + " --size 32x18";
        ASSERT_EQ(runLuxel(base + " --out " + path("one.exr")).exitCode, 0);
        const RunResult r = runLuxel(base + " --samples 4 --out " + path("four.exr"));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        luxel::ImageMetadata metadata;
        auto four = luxel::readExr(path("four.exr"), &metadata);
        auto one = luxel::readExr(path("one.exr"));
        ASSERT_TRUE(four.ok() && one.ok());
        const std::string* samples = luxel::findMetadata(metadata, "luxel.samples");
        ASSERT_NE(samples, nullptr);
        EXPECT_EQ(*samples, "4");
        double difference = 0.0, sum = 0.0;
        for (int y = 0; y < 18; ++y)
            for (int x = 0; x < 32; ++x) {
                difference += std::abs(four->at(x, y, 1) - one->at(x, y, 1));
                sum += one->at(x, y, 1);
            }
        EXPECT_GT(difference, 1e-3 * sum) << solver;
        EXPECT_LT(difference, 0.2 * sum) << solver;
    }
    const RunResult path =
        runLuxel("render " + kCottage + " --solver path --samples 4 --out " + this->path("p.exr"));
    EXPECT_EQ(path.exitCode, 1);
    EXPECT_NE(path.output.find("--solver path takes --spp"), std::string::npos) << path.output;
}

// --adaptive-samples: the cascades' picture draws thin-walls' lamp silhouette again by default,
// says how many pixels in the summary and the metadata, and 0 turns it off; other solvers refuse
// it.
TEST_F(CliRcVoxel, AdaptiveSamplesRefineTheLampsEdges) {
    const std::string thinWalls = kScenes + "voxel/thin-walls.json";
    const std::string base = "render " + thinWalls + " --solver rc --size 64x36 --backend cpu";
    const RunResult on = runLuxel(base + " --stats --out " + path("on.exr"));
    ASSERT_EQ(on.exitCode, 0) << on.output;
    EXPECT_NE(on.output.find("picture: 1 samples per pixel, "), std::string::npos) << on.output;
    EXPECT_EQ(on.output.find(" 0 pixels (0.00%) again"), std::string::npos) << on.output;
    const RunResult off = runLuxel(base + " --adaptive-samples 0 --stats --out " + path("off.exr"));
    ASSERT_EQ(off.exitCode, 0) << off.output;
    EXPECT_NE(off.output.find(" 0 pixels (0.00%) again with 0 samples"), std::string::npos)
        << off.output;
    luxel::ImageMetadata metadata;
    auto refined = luxel::readExr(path("on.exr"), &metadata);
    auto plain = luxel::readExr(path("off.exr"));
    ASSERT_TRUE(refined.ok() && plain.ok());
    const std::string* count = luxel::findMetadata(metadata, "luxel.rc.refined_pixels");
    ASSERT_NE(count, nullptr);
    EXPECT_GT(std::stoi(*count), 0);
    EXPECT_LT(std::stoi(*count), 64 * 36 / 32 + 1);
    int different = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) different += refined->at(x, y, 1) != plain->at(x, y, 1);
    EXPECT_EQ(different, std::stoi(*count));
    const RunResult path = runLuxel("render " + thinWalls + " --solver path --adaptive-samples 4" +
                                    " --out " + this->path("p.exr"));
    EXPECT_EQ(path.exitCode, 1);
    EXPECT_NE(path.output.find("--adaptive-samples applies to --solver rc"), std::string::npos)
        << path.output;
}

// `luxel info` says what the cascades of a voxel scene would take, as render plans them.
TEST_F(CliRcVoxel, InfoEstimatesTheCascades) {
    const RunResult r = runLuxel("info " + kCottage);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("cascades (rc)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("spacing 2, 4 levels, 1318 probes"), std::string::npos) << r.output;
    // The cottage's windows are glass: their runs are counted while building, not estimated.
    EXPECT_NE(r.output.find("+ runs through glass (checked while building; an automatic spacing "
                            "doubles where they do not fit)"),
              std::string::npos)
        << r.output;
    const RunResult render = runLuxel("render " + kCottage + " --solver rc --size 16x9 --out " +
                                      path("i.exr") + " --backend cpu");
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_NE(render.output.find("4 levels from spacing 2 (1318 probes)"), std::string::npos)
        << render.output;
}

// --backend gpu runs the lighting passes and the picture on the GPU (lavapipe in CI): the same
// picture (the GPU's differs from the CPU's by float rounding only,
// CascadesPictureGpu.CottageMatchesTheCpuPicture).
TEST_F(CliRcVoxel, GpuPassesGiveTheCpuPicture) {
    if (runLuxel("devices").exitCode != 0) GTEST_SKIP() << "no Vulkan device";
    const std::string common = "render " + kCottage + " --solver rc --size 48x27 --out ";
    const RunResult gpu = runLuxel(common + path("gpu.exr") + " --backend gpu");
    ASSERT_EQ(gpu.exitCode, 0) << gpu.output;
    EXPECT_NE(gpu.output.find("gpu: "), std::string::npos) << gpu.output;
    const RunResult cpu = runLuxel(common + path("cpu.exr") + " --backend cpu");
    ASSERT_EQ(cpu.exitCode, 0) << cpu.output;
    auto a = luxel::readExr(path("gpu.exr")), b = luxel::readExr(path("cpu.exr"));
    ASSERT_TRUE(a.ok() && b.ok());
    double difference = 0.0, sum = 0.0;
    for (int y = 0; y < 27; ++y)
        for (int x = 0; x < 48; ++x)
            for (int c = 0; c < 3; ++c) {
                difference += std::abs(a->at(x, y, c) - b->at(x, y, c));
                sum += b->at(x, y, c);
            }
    EXPECT_GT(sum, 0.0);
    EXPECT_LE(difference, 1e-5 * sum);
}

TEST_F(CliRcVoxel, RefusesItsOptionsWhereTheyDoNotApply) {
    const std::string out = " --out " + path("x.exr");
    expectError("render " + kCottage + " --rc-spacing 4" + out,
                "--rc-spacing applies to --solver rc on voxel scenes");
    expectError("render " + kScenes + "2d/room.json --solver rc --rc-spacing 4" + out,
                "--rc-spacing applies to --solver rc on voxel scenes");
    expectError("render " + kCottage + " --solver rc --filter trilinear" + out,
                "apply to the ray caster; --solver rc takes --rc-spacing, --bounces and --samples");
    expectError("render " + kCottage + " --solver rc --rc-spacing 3" + out,
                "cascade spacing must be a power of two");
    expectError("render " + kScenes + "octree/world.json --solver rc" + out,
                "--solver rc applies to 2D and voxel scenes");
    expectError("render " + kCottage + " --solver path --bounces 2" + out,
                "--bounces applies to 2D scenes");
    for (const char* spacing : {"-1", "128", "nan", "abc"}) {
        const RunResult r =
            runLuxel("render " + kCottage + " --solver rc --rc-spacing " + spacing + out);
        EXPECT_EQ(r.exitCode, 1) << spacing << ": " << r.output;
        EXPECT_NE(r.output.find("--rc-spacing"), std::string::npos) << r.output;
    }
    const RunResult r = runLuxel("render " + kCottage + " --solver rc --bounces 5000" + out);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("bounces"), std::string::npos) << r.output;
}

}  // namespace
