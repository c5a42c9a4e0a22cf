// `luxel render --solver path` end to end: a shipped voxel scene path traced at a small size
// (image, provenance, summary), on the GPU too (--backend gpu; without a device an error, and
// auto the CPU), and the refusals: path on a 2D or octree scene, --spp without --solver path, the
// ray caster's flags with it, bad sample counts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_metadata.h"
#include "luxel/core/memory.h"
#include "support/cli_fixture.h"

namespace {

using luxel::test::runLuxel;
using luxel::test::RunResult;

// luxel with no Vulkan driver to find.
RunResult runWithoutVulkan(const std::string& args) {
    return luxel::test::runCommand(
        "VK_DRIVER_FILES=/nonexistent.json VK_ICD_FILENAMES=/nonexistent.json " +
        std::string(LUXEL_CLI_PATH) + " " + args);
}

class CliPath : public luxel::test::CliFixture {};

const std::string kScenes = std::string(LUXEL_SOURCE_DIR) + "/scenes/";
const std::string kTerrain = kScenes + "voxel/terrain.json";

TEST_F(CliPath, PathTracesAVoxelScene) {
    const RunResult r =
        runLuxel("render " + kTerrain +
                 " --solver path --spp 2 --seed 7 --max-bounces 3 --size 32x18 "
                 "--out " +
                 path("p.exr") + " --png " + path("p.png") + " --std-error " + path("e.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("path traced"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("wrote " + path("p.exr") + ", " + path("p.png") + ", " + path("e.exr")),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("path tracing: 2 samples per pixel, at most 3 bounces, seed 7, "
                            "relative standard error "),
              std::string::npos)
        << r.output;
    luxel::ImageMetadata metadata;
    auto exr = luxel::readExr(path("p.exr"), &metadata);
    ASSERT_TRUE(exr.ok()) << exr.error().message();
    EXPECT_EQ(exr->width(), 32);
    EXPECT_EQ(exr->height(), 18);
    double sum = 0.0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 32; ++x) sum += exr->at(x, y, 1);
    EXPECT_TRUE(std::isfinite(sum));
    EXPECT_GT(sum, 0.0);
    auto value = [&](const char* key) {
        const std::string* v = luxel::findMetadata(metadata, key);
        return v ? *v : std::string("(missing)");
    };
    EXPECT_EQ(value("luxel.solver"), "path");
    EXPECT_EQ(value("luxel.samples"), "2");
    EXPECT_EQ(value("luxel.seed"), "7");
    EXPECT_TRUE(luxel::readPng(path("p.png")).ok());

    // The standard error: as large as the image, finite, >= 0, > 0 where samples differ.
    luxel::ImageMetadata errorMetadata;
    auto error = luxel::readExr(path("e.exr"), &errorMetadata);
    ASSERT_TRUE(error.ok()) << error.error().message();
    ASSERT_EQ(error->width(), 32);
    ASSERT_EQ(error->height(), 18);
    int noisy = 0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 32; ++x) {
            const float e = error->at(x, y, 1);
            ASSERT_TRUE(std::isfinite(e) && e >= 0.0f) << e;
            noisy += e > 0.0f;
        }
    EXPECT_GT(noisy, 0);
    const std::string* content = luxel::findMetadata(errorMetadata, "luxel.content");
    ASSERT_NE(content, nullptr);
    EXPECT_EQ(*content, "standard error, linear");

    // Seed 7 again: an identical image.
    const RunResult again = runLuxel("render " + kTerrain +
                                     " --solver path --spp 2 --seed 7 --max-bounces 3 "
                                     "--size 32x18 --quiet --out " +
                                     path("q.exr"));
    ASSERT_EQ(again.exitCode, 0) << again.output;
    auto second = luxel::readExr(path("q.exr"));
    ASSERT_TRUE(second.ok());
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(second->at(x, y, 0), exr->at(x, y, 0));
}

// --backend gpu traces on the GPU (lavapipe in CI) with the CPU's random numbers: the same image
// within its noise, and the backend in the provenance.
TEST_F(CliPath, GpuBackendTracesTheSameImage) {
    const std::string common = "render " + kTerrain +
                               " --solver path --spp 8 --seed 3 --max-bounces 3 --size 24x14 "
                               "--std-error ";
    // No driver: --backend gpu fails with the reason, auto falls back to the CPU.
    RunResult r =
        runWithoutVulkan(common + path("ne.exr") + " --out " + path("n.exr") + " --backend gpu");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("luxel: error: --backend gpu: "), std::string::npos) << r.output;
    r = runWithoutVulkan(common + path("ae.exr") + " --out " + path("a.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("; using the CPU"), std::string::npos) << r.output;
    if (runLuxel("devices").exitCode != 0) GTEST_SKIP() << "no Vulkan device";
    r = runLuxel(common + path("ge.exr") + " --out " + path("g.exr") + " --backend gpu");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("gpu: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("path tracing: 8 samples per pixel"), std::string::npos) << r.output;
    r = runLuxel(common + path("ce.exr") + " --out " + path("c.exr") + " --backend cpu");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    luxel::ImageMetadata metadata;
    auto gpu = luxel::readExr(path("g.exr"), &metadata), cpu = luxel::readExr(path("c.exr"));
    auto gpuError = luxel::readExr(path("ge.exr")), cpuError = luxel::readExr(path("ce.exr"));
    ASSERT_TRUE(gpu.ok() && cpu.ok() && gpuError.ok() && cpuError.ok());
    const std::string* backend = luxel::findMetadata(metadata, "luxel.backend");
    ASSERT_NE(backend, nullptr);
    EXPECT_EQ(*backend, "gpu");
    double gpuSum = 0.0, cpuSum = 0.0;
    int within = 0;
    for (int y = 0; y < 14; ++y)
        for (int x = 0; x < 24; ++x) {
            const double a = gpu->at(x, y, 1), b = cpu->at(x, y, 1);
            const double se = std::hypot(gpuError->at(x, y, 1), cpuError->at(x, y, 1));
            within += std::abs(a - b) <= 4.0 * se + 1e-4 * std::abs(b);
            gpuSum += a, cpuSum += b;
        }
    EXPECT_GT(cpuSum, 0.0);
    EXPECT_NEAR(gpuSum, cpuSum, 0.02 * cpuSum);
    EXPECT_GE(within, 24 * 14 * 98 / 100);
}

// `luxel info` says what `render --solver path` would take on the CPU and on the GPU: the
// running sums (64 bytes a pixel; 112 with the GPU's download), the world's upload, the device's
// sums (48 bytes a pixel) and the emitters (16 bytes each). The cottage's lamps and windows emit.
TEST_F(CliPath, InfoEstimatesThePathTracer) {
    const RunResult r = runLuxel("info " + kScenes + "voxel/cottage.json --size 64x48");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::uint64_t pixels = 64 * 48;
    EXPECT_NE(r.output.find("  path (cpu)         " + luxel::formatBytes(pixels * 64) +
                            ": running sums of 64x48 pixels\n"),
              std::string::npos)
        << r.output;
    const std::string gpu =
        "  path (gpu)         host " + luxel::formatBytes(pixels * 112) + ", device ";
    const std::size_t at = r.output.find(gpu);
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_NE(r.output.find(", sums " + luxel::formatBytes(pixels * 48) + ", ", at),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(" emitters ", at), std::string::npos) << r.output;
}

TEST_F(CliPath, RefusesPathWhereItDoesNotApply) {
    const std::string out = " --out " + path("x.exr");
    expectError("render " + kScenes + "2d/room.json --solver path" + out,
                "--solver path applies to voxel scenes; " + kScenes + "2d/room.json is a 2D scene");
    expectError("render " + kScenes + "octree/terrain.json --solver path" + out,
                "--solver path applies to voxel scenes");
    expectError("render " + kTerrain + " --spp 4" + out, "--spp applies to --solver path");
    expectError("render " + kTerrain + " --max-bounces 2" + out,
                "--max-bounces applies to --solver path");
    expectError("render " + kTerrain + " --solver path --samples 4" + out,
                "apply to the ray caster; --solver path takes --spp");
    expectError("render " + kTerrain + " --solver path --std-error " + path("e.png") + out,
                "' must be an .exr file");
    expectError("render " + kTerrain + " --std-error " + path("e.exr") + out,
                "--std-error applies to --solver path");
    expectError(
        "render " + kTerrain + " --solver pt" + out,
        "--solver 'pt' is not one of: reference, hrc, rc (voxel scenes: raycast, path, ao, rc)");
    // A 2D solver on a voxel scene is refused as before.
    expectError("render " + kTerrain + " --solver hrc" + out, "--solver applies to 2D scenes");
    for (const char* spp : {"0", "-3", "1e9", "nan"}) {
        const RunResult r = runLuxel("render " + kTerrain + " --solver path --spp " + spp + out);
        EXPECT_EQ(r.exitCode, 1) << spp << ": " << r.output;
        EXPECT_NE(r.output.find("--spp"), std::string::npos) << r.output;
    }
}

}  // namespace
