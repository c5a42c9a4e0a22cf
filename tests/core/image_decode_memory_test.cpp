// Image readers refuse before allocating: a PNG header declaring more pixel data than deflate can
// produce from the file, and any PNG or EXR whose decode does not fit in the memory left
// (checkMemory, honouring RLIMIT_AS), with one message naming the file and the size.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "luxel/core/image_io.h"
#include "luxel/gi2d/scene2d_json.h"
#include "support/memory_limit.h"
#include "support/temp_dir.h"

namespace luxel {
namespace {

constexpr std::uint64_t kMiB = 1024 * 1024;

std::uint32_t crc32(const std::vector<unsigned char>& bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void appendChunk(std::vector<unsigned char>& png, const char* type,
                 const std::vector<unsigned char>& data) {
    auto be32 = [&](std::uint32_t v, std::vector<unsigned char>& out) {
        for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
    };
    be32(static_cast<std::uint32_t>(data.size()), png);
    std::vector<unsigned char> typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    png.insert(png.end(), typed.begin(), typed.end());
    be32(crc32(typed), png);
}

// A 68-byte PNG whose header declares width x height RGBA and whose data stops after 11 bytes.
std::vector<unsigned char> truncatedPng(std::uint32_t width, std::uint32_t height) {
    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
    std::vector<unsigned char> ihdr;
    for (std::uint32_t v : {width, height}) {
        for (int s = 24; s >= 0; s -= 8) ihdr.push_back(static_cast<unsigned char>(v >> s));
    }
    for (unsigned char b : {8, 6, 0, 0, 0}) ihdr.push_back(b);  // 8-bit RGBA, not interlaced
    appendChunk(png, "IHDR", ihdr);
    appendChunk(png, "IDAT", {0x78, 0xda, 0xed, 0xc1, 0x01, 0x0d, 0x00, 0x00, 0x00, 0xc2, 0xa0});
    appendChunk(png, "IEND", {});
    return png;
}

class ImageDecodeMemory : public test::TempDirTest {};

TEST_F(ImageDecodeMemory, PngDeclaringMoreThanDeflateCanHoldIsRefusedUpFront) {
    const std::vector<unsigned char> bytes = truncatedPng(16384, 16384);
    ASSERT_EQ(bytes.size(), 68u);
    const std::string file = path("huge.png");
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(68));
    // Refused before the 1 GiB decode buffer: it must also fail this way with only 64 MiB left.
    const int code = test::runUnderMemoryLimit(64 * kMiB, [&] {
        const Result<Image> image = readPng(file);
        if (image.ok()) return 1;
        const std::string message = image.error().message();
        if (message.find("cannot read PNG '" + file + "'") == std::string::npos) return 2;
        if (message.find("declares 16384x16384 pixels") == std::string::npos) return 3;
        if (message.find("68 bytes") == std::string::npos) return 4;
        return 0;
    });
    EXPECT_EQ(code, 0);
}

TEST_F(ImageDecodeMemory, PlausiblePngsStillRead) {
    // The same header at a size whose data the file could hold gets past the check and fails
    // at the truncated data instead; a complete file reads.
    const std::vector<unsigned char> bytes = truncatedPng(4, 4);
    const std::string file = path("small.png");
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    const Result<Image> truncated = readPng(file);
    ASSERT_FALSE(truncated.ok());
    EXPECT_EQ(truncated.error().message().find("declares"), std::string::npos)
        << truncated.error().message();
    Image image(64, 48, 3);
    ASSERT_TRUE(writePng(path("ok.png"), image).ok());
    EXPECT_TRUE(readPng(path("ok.png")).ok());
}

// 2048 x 2048 RGB: 48 MiB of floats (and one 6 KiB row of decoded bytes), a small file.
Image largeFlatImage() {
    Image image(2048, 2048, 3);
    for (std::size_t i = 0; i < image.size(); ++i) image.data()[i] = 0.25f;
    return image;
}

TEST_F(ImageDecodeMemory, PngThatDoesNotFitIsRefusedBeforeDecoding) {
    const std::string file = path("flat.png");
    ASSERT_TRUE(writePng(file, largeFlatImage()).ok());
    const int code = test::runUnderMemoryLimit(24 * kMiB, [&] {
        const Result<Image> image = readPng(file);
        if (image.ok()) return 1;
        const std::string message = image.error().message();
        if (message.find("decoding PNG '" + file + "' (2048x2048) needs 48.0 MiB, only ") != 0) {
            return 2;
        }
        return 0;
    });
    EXPECT_EQ(code, 0);
    EXPECT_TRUE(readPng(file).ok()) << "it reads without the limit";
}

TEST_F(ImageDecodeMemory, ExrThatDoesNotFitIsRefusedBeforeDecoding) {
    const std::string file = path("flat.exr");
    ASSERT_TRUE(writeExr(file, largeFlatImage()).ok());
    const int code = test::runUnderMemoryLimit(24 * kMiB, [&] {
        const Result<Image> image = readExr(file);
        if (image.ok()) return 1;
        const std::string message = image.error().message();
        if (message.find("decoding EXR '" + file + "' (2048x2048) needs 48.0 MiB, only ") != 0) {
            return 2;
        }
        return 0;
    });
    EXPECT_EQ(code, 0);
    EXPECT_TRUE(readExr(file).ok()) << "it reads without the limit";
}

TEST_F(ImageDecodeMemory, SceneImageLayerThatDoesNotFitNamesTheLayer) {
    ASSERT_TRUE(writePng(path("layer.png"), largeFlatImage()).ok());
    const std::string scene = path("scene.json");
    std::ofstream(scene) << R"({"canvas": [64, 64],
  "shapes": [{"type": "image", "emission": "layer.png"}]})";
    const int code = test::runUnderMemoryLimit(24 * kMiB, [&] {
        const Result<gi2d::Scene2D> loaded = gi2d::loadScene2D(scene);
        if (loaded.ok()) return 1;
        const std::string message = loaded.error().message();
        if (message.find(scene) == std::string::npos) return 2;
        if (message.find("cannot load image 'layer.png'") == std::string::npos) return 3;
        if (message.find("decoding PNG") == std::string::npos) return 4;
        if (message.find("needs 48.0 MiB, only ") == std::string::npos) return 5;
        return 0;
    });
    EXPECT_EQ(code, 0);
}

}  // namespace
}  // namespace luxel
