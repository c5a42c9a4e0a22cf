// decodePng / decodeExr: the in-memory readers (used by the fuzz targets) give exactly what the
// file readers give for the same bytes, and every bad buffer is an Error naming the source.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "luxel/core/image_io.h"
#include "support/temp_dir.h"

namespace luxel {
namespace {

class ImageDecodeTest : public test::TempDirTest {};

std::vector<std::uint8_t> bytesOf(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Image gradient(int width, int height, int channels, float scale) {
    Image image(width, height, channels);
    for (std::size_t i = 0; i < image.size(); ++i) {
        image.data()[i] = scale * static_cast<float>(i % 97) / 96.0f;
    }
    return image;
}

void expectSameImage(const Image& a, const Image& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    ASSERT_EQ(a.channels(), b.channels());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a.data()[i], b.data()[i]) << i;
}

TEST_F(ImageDecodeTest, PngFromMemoryMatchesTheFileReader) {
    for (int channels : {1, 2, 3, 4}) {
        SCOPED_TRACE(channels);
        const std::string file = path("g.png");
        ASSERT_TRUE(writePng(file, gradient(13, 7, channels, 1.0f)).ok());
        for (PngEncoding encoding : {PngEncoding::Srgb, PngEncoding::Linear}) {
            const Result<Image> fromFile = readPng(file, encoding);
            const Result<Image> fromMemory = decodePng(bytesOf(file), "g.png", encoding);
            ASSERT_TRUE(fromFile.ok()) << fromFile.error().message();
            ASSERT_TRUE(fromMemory.ok()) << fromMemory.error().message();
            expectSameImage(*fromFile, *fromMemory);
        }
    }
}

TEST_F(ImageDecodeTest, ExrFromMemoryMatchesTheFileReader) {
    for (int channels : {1, 3, 4}) {
        SCOPED_TRACE(channels);
        const std::string file = path("g.exr");
        ASSERT_TRUE(writeExr(file, gradient(11, 5, channels, 40.0f)).ok());
        const Result<Image> fromFile = readExr(file);
        const Result<Image> fromMemory = decodeExr(bytesOf(file), "g.exr");
        ASSERT_TRUE(fromFile.ok()) << fromFile.error().message();
        ASSERT_TRUE(fromMemory.ok()) << fromMemory.error().message();
        expectSameImage(*fromFile, *fromMemory);
    }
}

TEST_F(ImageDecodeTest, ShortAndCutBuffersAreErrorsNamingTheSource) {
    const std::string png = path("c.png");
    const std::string exr = path("c.exr");
    ASSERT_TRUE(writePng(png, gradient(16, 16, 4, 1.0f)).ok());
    ASSERT_TRUE(writeExr(exr, gradient(16, 16, 4, 1.0f)).ok());
    const std::vector<std::uint8_t> pngBytes = bytesOf(png);
    const std::vector<std::uint8_t> exrBytes = bytesOf(exr);
    for (std::size_t keep : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{8},
                             std::size_t{30}, pngBytes.size() / 2, pngBytes.size() - 1}) {
        SCOPED_TRACE(keep);
        const std::span<const std::uint8_t> cut(pngBytes.data(), keep);
        const Result<Image> image = decodePng(cut, "cut.png");
        ASSERT_FALSE(image.ok());
        EXPECT_NE(image.error().message().find("'cut.png'"), std::string::npos)
            << image.error().message();
    }
    for (std::size_t keep : {std::size_t{0}, std::size_t{3}, std::size_t{100}, exrBytes.size() / 2,
                             exrBytes.size() - 1}) {
        SCOPED_TRACE(keep);
        const std::span<const std::uint8_t> cut(exrBytes.data(), keep);
        const Result<Image> image = decodeExr(cut, "cut.exr");
        ASSERT_FALSE(image.ok());
        EXPECT_NE(image.error().message().find("'cut.exr'"), std::string::npos)
            << image.error().message();
    }
}

}  // namespace
}  // namespace luxel
