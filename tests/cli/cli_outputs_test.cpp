// What `luxel` writes and says around a render: provenance metadata read back from its images,
// exit codes of command-line errors, --png without --out, warnings for silent emitters and
// blown-out pictures, --exposure auto, and compare-solvers reusing a reference.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_metadata.h"
#include "support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;

using luxel::ImageMetadata;
using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliOutputs : public luxel::test::CliFixture {
  protected:
    // A lamp and an occluder; `intensity` scales the lamp, `lampAbsorption` is its JSON material.
    std::string scene(const std::string& name, double intensity = 1,
                      const std::string& lampMaterial = "\"opaque\": true") {
        return write(name, R"({
  "canvas": [48, 32],
  "shapes": [
    {"type": "circle", "name": "lamp", "center": [12, 16], "radius": 5, "emission": [2, 1, 0.5],
     "intensity": )" + std::to_string(intensity) +
                               ", " + lampMaterial + R"(},
    {"type": "box", "min": [24, 4], "max": [28, 20], "opaque": true}
  ]
})");
    }

    ImageMetadata metadataOf(const std::string& file) {
        ImageMetadata metadata;
        auto image = luxel::readImage(file, &metadata);
        EXPECT_TRUE(image) << image.error().message();
        return metadata;
    }

    static std::string value(const ImageMetadata& metadata, const std::string& key) {
        const std::string* v = luxel::findMetadata(metadata, key);
        return v != nullptr ? *v : "(missing " + key + ")";
    }

    static std::string fileHash(const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in),
                                std::istreambuf_iterator<char>()};
        return luxel::fnv1a64Hex(bytes);
    }
};

TEST_F(CliOutputs, RenderedImagesCarrySolverSettingsAndSceneHash) {
    const std::string file = scene("lamp.json");
    const RunResult r = runLuxel("render " + file + " --solver hrc --quiet --out " + path("f.exr") +
                                 " --png " + path("d.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const std::string& image : {path("f.exr"), path("d.png")}) {
        const ImageMetadata m = metadataOf(image);
        EXPECT_EQ(value(m, "luxel.solver"), "hrc") << image;
        EXPECT_EQ(value(m, "luxel.scene"), "lamp.json");
        EXPECT_EQ(value(m, "luxel.scene.fnv1a64"), fileHash(file));
        EXPECT_EQ(value(m, "luxel.canvas"), "48x32");
        EXPECT_EQ(value(m, "luxel.backend"), "cpu");
        EXPECT_NE(luxel::findMetadata(m, "luxel.hrc.traced_levels"), nullptr);
        EXPECT_NE(luxel::findMetadata(m, "luxel.render.seconds"), nullptr);
        EXPECT_NE(luxel::findMetadata(m, "luxel.version"), nullptr);
        EXPECT_EQ(value(m, "luxel.date").size(), 20u);  // 2026-01-02T03:04:05Z
    }
    EXPECT_EQ(value(metadataOf(path("f.exr")), "luxel.content"), "fluence, linear");
    EXPECT_EQ(value(metadataOf(path("d.png")), "luxel.content"), "display, tonemapped");

    const RunResult reference =
        runLuxel("render " + file + " --rays 8 --seed 3 --quiet --out " + path("r.png"));
    ASSERT_EQ(reference.exitCode, 0) << reference.output;
    const ImageMetadata m = metadataOf(path("r.png"));
    EXPECT_EQ(value(m, "luxel.solver"), "reference");
    EXPECT_EQ(value(m, "luxel.rays"), "8");
    EXPECT_EQ(value(m, "luxel.seed"), "3");

    // `luxel info IMAGE` prints them.
    const RunResult info = runLuxel("info " + path("f.exr"));
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("48x32, 3 channels (EXR"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("luxel.scene.fnv1a64"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find(fileHash(file)), std::string::npos) << info.output;
}

TEST_F(CliOutputs, VoxelRendersCarryMetadataToo) {
    const std::string file = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json";
    const RunResult r =
        runLuxel("render " + file + " --size 64x36 --backend cpu --quiet --png " + path("t.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const ImageMetadata m = metadataOf(path("t.png"));
    EXPECT_EQ(value(m, "luxel.solver"), "voxel");
    EXPECT_EQ(value(m, "luxel.scene.fnv1a64"), fileHash(file));
    EXPECT_EQ(value(m, "luxel.canvas"), "64x36");
    EXPECT_NE(luxel::findMetadata(m, "luxel.samples"), nullptr);
}

TEST_F(CliOutputs, PngAloneIsEnoughAndNeitherIsAnError) {
    const std::string file = scene("lamp.json");
    const RunResult r = runLuxel("render " + file + " --solver hrc --quiet --png " + path("d.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("d.png")));
    expectError("render " + file + " --solver hrc", "nothing to write");
}

TEST_F(CliOutputs, EveryCommandLineErrorExitsOne) {
    const std::string file = scene("lamp.json");
    expectError("render", "scene is required");  // missing argument
    expectError("render " + file + " --png " + path("d.png") + " --frobnicate", "--frobnicate");
    expectError("render " + file + " --png " + path("d.png") + " --rays many", "--rays");
    expectError("render " + file + " --png " + path("d.png") + " --exposure bright", "--exposure");
    expectError("render " + path("missing.json") + " --png " + path("d.png"), "missing.json");
    expectError("frobnicate", "subcommand");  // unknown command
    expectError("", "subcommand");
    // Asking for help or the version is not an error.
    const RunResult help = runLuxel("render --help");
    EXPECT_EQ(help.exitCode, 0) << help.output;
    EXPECT_NE(help.output.find("--exposure"), std::string::npos);
    const RunResult version = runLuxel("--version");
    EXPECT_EQ(version.exitCode, 0) << version.output;
    EXPECT_EQ(version.output.rfind("luxel ", 0), 0u) << version.output;
}

TEST_F(CliOutputs, EmitterWithoutAbsorptionIsWarnedAbout) {
    const std::string file = scene("clear-lamp.json", 1, "\"absorption\": 0");
    const RunResult info = runLuxel("info " + file);
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("luxel: warning: "), std::string::npos) << info.output;
    EXPECT_NE(
        info.output.find("shapes[0] 'lamp' has emission but absorption 0 in red, green and blue"),
        std::string::npos)
        << info.output;
    const RunResult render = runLuxel("render " + file + " --solver hrc --png " + path("d.png"));
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_NE(render.output.find("absorption 0"), std::string::npos) << render.output;
    const RunResult quiet =
        runLuxel("render " + file + " --solver hrc --quiet --png " + path("d.png"));
    EXPECT_EQ(quiet.output, "") << quiet.output;
    // Absorption in only some channels: the others are named.
    const std::string partial = scene("partial.json", 1, "\"absorption\": [1, 0, 1]");
    const RunResult some = runLuxel("info " + partial);
    EXPECT_NE(some.output.find("absorption 0 in green:"), std::string::npos) << some.output;
    // The background too.
    const std::string glow = write("glow.json", R"({"canvas": [16, 16],
        "background": {"emission": 1, "absorption": 0}, "shapes": []})");
    EXPECT_NE(runLuxel("info " + glow).output.find("the background has emission"),
              std::string::npos);
}

TEST_F(CliOutputs, BlownOutPictureIsWarnedAboutWithAnExposure) {
    const std::string file = scene("bright.json", 1000);
    const RunResult r = runLuxel("render " + file + " --solver hrc --png " + path("d.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto at = r.output.find("luxel: warning: ");
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_NE(r.output.find("clipped to white", at), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("try --exposure -", at), std::string::npos) << r.output;
    // The suggested exposure, or auto, leaves nothing to warn about.
    const RunResult autoRun =
        runLuxel("render " + file + " --solver hrc --exposure auto --png " + path("d.png"));
    EXPECT_EQ(autoRun.output.find("warning"), std::string::npos) << autoRun.output;
    // A PNG --out counts too; --quiet silences it.
    EXPECT_NE(runLuxel("render " + file + " --solver hrc --out " + path("f.png"))
                  .output.find("clipped to white"),
              std::string::npos);
    EXPECT_EQ(runLuxel("render " + file + " --solver hrc --quiet --out " + path("f.png")).output,
              "");
}

TEST_F(CliOutputs, AutoExposureScalesWithTheLight) {
    const std::string dim = scene("dim.json", 1);
    const std::string bright = scene("bright.json", 100);
    const RunResult a =
        runLuxel("render " + dim + " --solver hrc --exposure auto --png " + path("dim.png"));
    const RunResult b = runLuxel(
        "render " + bright + " --solver hrc --exposure auto --quiet --png " + path("bright.png"));
    ASSERT_EQ(a.exitCode, 0) << a.output;
    ASSERT_EQ(b.exitCode, 0) << b.output;
    EXPECT_NE(a.output.find("exposure auto: "), std::string::npos) << a.output;
    const ImageMetadata ma = metadataOf(path("dim.png")), mb = metadataOf(path("bright.png"));
    EXPECT_EQ(value(ma, "luxel.exposure.auto"), "yes");
    const double stopsDim = std::stod(value(ma, "luxel.exposure"));
    const double stopsBright = std::stod(value(mb, "luxel.exposure"));
    // 100x the light -> 1/100 of the exposure (log2(100) = 6.64 stops), within 1%.
    EXPECT_NEAR(std::exp2(stopsDim - stopsBright), 100.0, 1.0) << stopsDim << " " << stopsBright;
}

// Neither warning fires on the scenes luxel ships (at their own sizes; voxel and octree scenes
// smaller, as their pictures do not depend on the size).
TEST_F(CliOutputs, ShippedScenesRenderWithoutWarnings) {
    const std::string root = std::string(LUXEL_SOURCE_DIR) + "/scenes/";
    for (const auto& entry : fs::directory_iterator(root + "2d")) {
        if (entry.path().extension() != ".json") continue;
        const std::string file = entry.path().string();
        const RunResult info = runLuxel("info " + file);
        EXPECT_EQ(info.output.find("warning"), std::string::npos) << file << "\n" << info.output;
        const RunResult r =
            runLuxel("render " + file + " --solver hrc --backend cpu --png " + path("d.png"));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << file << "\n" << r.output;
    }
    for (const char* name : {"voxel/terrain.json", "voxel/glass.json", "voxel/garden.json",
                             "voxel/fence.json", "octree/world.json", "octree/phantom.json"}) {
        const RunResult r = runLuxel("render " + root + name +
                                     " --size 160x90 --backend cpu --png " + path("v.png"));
        EXPECT_EQ(r.exitCode, 0) << name << "\n" << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << name << "\n" << r.output;
    }
}

TEST_F(CliOutputs, CompareSolversReusesACheckedReference) {
    const std::string file = scene("lamp.json");
    ASSERT_EQ(runLuxel("render " + file + " --rays 16 --quiet --out " + path("ref.exr")).exitCode,
              0);
    const RunResult r = runLuxel("compare-solvers " + file + " --reference " + path("ref.exr") +
                                 " --grid " + path("grid.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("reference: 16 rays/pixel, from " + path("ref.exr")), std::string::npos)
        << r.output;
    // Labelled panels; the grid's metadata lists what each panel shows.
    const ImageMetadata m = metadataOf(path("grid.png"));
    EXPECT_EQ(value(m, "luxel.solver"), "compare-solvers");
    EXPECT_NE(value(m, "luxel.panel2.hrc").find("rel. L1"), std::string::npos);
    EXPECT_EQ(value(m, "luxel.scene.fnv1a64"), fileHash(file));

    // The wrong size, a non-reference render and another scene are refused.
    expectError("compare-solvers " + file + " --size 24x16 --reference " + path("ref.exr"),
                "renders at 24x16");
    ASSERT_EQ(
        runLuxel("render " + file + " --solver hrc --quiet --out " + path("hrc.exr")).exitCode, 0);
    expectError("compare-solvers " + file + " --reference " + path("hrc.exr"), "hrc solver");
    const std::string other = scene("other.json", 2);
    expectError("compare-solvers " + other + " --reference " + path("ref.exr"),
                "another version of");
    expectError("compare-solvers " + file + " --reference " + path("grid.png"), "fluence EXR");
}

}  // namespace
