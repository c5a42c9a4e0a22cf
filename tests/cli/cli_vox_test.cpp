// `luxel` on MagicaVoxel files end to end: render and info open a .vox directly (a framing
// camera, warnings printed as "luxel: warning:"), --frame picks an animation frame, and convert
// writes .vox files from scenes and .vox files.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "luxel/core/image_io.h"
#include "luxel/voxel/vox_import.h"
#include "support/cli_fixture.h"
#include "support/vox_writer.h"

namespace {

namespace vw = luxel::test::vox;
using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliVox : public luxel::test::CliFixture {
  protected:
    std::string writeBytes(const std::string& name, const vw::Bytes& bytes) {
        const std::string p = path(name);
        std::ofstream(p, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
        return p;
    }
};

// A floor and a pillar that moves between frames 0 and 1, plus a camera chunk luxel ignores.
vw::Bytes animatedFile() {
    std::vector<vw::Voxel4> floor;
    for (std::uint8_t x = 0; x < 16; ++x)
        for (std::uint8_t y = 0; y < 16; ++y) floor.push_back({x, y, 0, 1});
    std::vector<vw::Voxel4> pillar;
    for (std::uint8_t z = 0; z < 6; ++z) pillar.push_back({0, 0, z, 2});
    return vw::file(vw::cat(
        {vw::model(16, 16, 1, floor), vw::model(1, 1, 6, pillar), vw::transform(0, 1),
         vw::group(1, {2, 4}), vw::transform(2, 3), vw::shape(3, {{0, -1}}),
         vw::transform(4, 5, {{{"_f", "0"}, {"_t", "-5 -5 3"}}, {{"_f", "1"}, {"_t", "5 5 3"}}}),
         vw::shape(5, {{1, -1}}), vw::chunk("rCAM", vw::cat({vw::ints({0}), vw::dict({})}))}));
}

TEST_F(CliVox, RenderAndInfoOpenAVoxDirectly) {
    const std::string vox = writeBytes("m.vox", animatedFile());
    RunResult r = runLuxel("render " + vox + " --backend cpu --size 64x36 --out " + path("a.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("luxel: warning: " + vox +
                            ": chunk rCAM (cameras; luxel frames the model itself) ignored"),
              std::string::npos)
        << r.output;
    auto image = luxel::readPng(path("a.png"));
    ASSERT_TRUE(image.ok()) << image.error().message();
    EXPECT_EQ(image->width(), 64);
    EXPECT_EQ(image->height(), 36);

    r = runLuxel("info " + vox);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("world              16x6x16 voxels in chunks of 32, 261 solid"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("lighting           physical"), std::string::npos) << r.output;

    // The shipped sample opens too.
    r = runLuxel("info " + std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/sample.vox");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("24x16x24 voxels"), std::string::npos) << r.output;
}

TEST_F(CliVox, FramePicksTheAnimationFrame) {
    const std::string vox = writeBytes("m.vox", animatedFile());
    ASSERT_EQ(
        runLuxel("render " + vox + " --backend cpu --size 64x36 --out " + path("f0.png")).exitCode,
        0);
    RunResult r =
        runLuxel("render " + vox + " --backend cpu --size 64x36 --frame 1 --out " + path("f1.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto f0 = luxel::readPng(path("f0.png")), f1 = luxel::readPng(path("f1.png"));
    ASSERT_TRUE(f0.ok() && f1.ok());
    const std::vector<float> a(f0->data(), f0->data() + f0->size()),
        b(f1->data(), f1->data() + f1->size());
    EXPECT_NE(a, b);  // the pillar moved
    r = runLuxel("render " + vox + " --backend cpu --size 64x36 --frame 7 --out " + path("f7.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("frame 7 is past the last keyframe (1)"), std::string::npos)
        << r.output;
    expectError("render " + vox + " --frame -1 --out " + path("x.png"), "--frame");
    // info reads the same frame; a 2D scene has no frames.
    r = runLuxel("info " + vox + " --frame 7");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("frame 7 is past the last keyframe (1)"), std::string::npos)
        << r.output;
    const std::string flat = write("flat.json", R"({"canvas": [16, 16], "shapes": []})");
    expectError("render " + flat + " --frame 0 --out " + path("x.png"),
                "--frame applies to MagicaVoxel worlds");
}

TEST_F(CliVox, ConvertWritesVoxFromVoxAndFromScenes) {
    const std::string vox = writeBytes("m.vox", animatedFile());
    RunResult r = runLuxel("convert " + vox + " " + path("out.vox") + " --frame 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("wrote " + path("out.vox")), std::string::npos) << r.output;
    auto original = luxel::voxel::readVoxFile(vox, {32, 1});
    auto converted = luxel::voxel::readVoxFile(path("out.vox"));
    ASSERT_TRUE(original.ok() && converted.ok());
    EXPECT_TRUE(original->world == converted->world);

    const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json";
    r = runLuxel("convert " + scene + " " + path("cottage.vox"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto cottage = luxel::voxel::readVoxFile(path("cottage.vox"));
    ASSERT_TRUE(cottage.ok()) << cottage.error().message();
    EXPECT_EQ(cottage->world.size(), (luxel::Int3{24, 16, 24}));
    EXPECT_EQ(cottage->materials.size(), 2u);  // the window glass and the glowing flowers

    expectError("convert " + vox + " " + path("out.png"), "the output must end in .vox");
    expectError("convert " + path("missing.vox") + " " + path("o.vox"), "missing.vox");
    const vw::Bytes bytes = animatedFile();
    const std::string cut = writeBytes("cut.vox", vw::Bytes(bytes.begin(), bytes.begin() + 60));
    expectError("convert " + cut + " " + path("o.vox"), "cut.vox: byte ");
    expectError("render " + cut + " --out " + path("o.png"), "cut.vox: byte ");
}

}  // namespace
