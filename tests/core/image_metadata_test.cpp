// Image metadata: round trips through PNG (tEXt, iTXt) and EXR (string attributes), the checks on
// keys and values, and the FNV-1a fingerprint.
#include "luxel/core/image_metadata.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "luxel/core/image_io.h"
#include "support/temp_dir.h"

namespace luxel {
namespace {

namespace fs = std::filesystem;

class ImageMetadataTest : public test::TempDirTest {};

Image gradient() {
    Image image(5, 3, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) image.setRgb(x, y, Rgb(0.1f * x, 0.2f * y, 0.5f));
    }
    return image;
}

ImageMetadata sample() {
    return {{"luxel.solver", "hrc"},
            {"luxel.scene", "r\xC3\xA4um.json"},  // UTF-8: iTXt in PNG
            {"luxel.note", "two\nlines"},
            {"luxel.empty", ""}};
}

ImageMetadata sorted(ImageMetadata m) {
    std::sort(m.begin(), m.end(),
              [](const MetadataEntry& a, const MetadataEntry& b) { return a.key < b.key; });
    return m;
}

std::vector<std::uint8_t> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(ImageMetadataTest, PngRoundTripKeepsEveryEntryInOrder) {
    ASSERT_TRUE(writePng(path("a.png"), gradient(), PngEncoding::Srgb, sample()));
    ImageMetadata read;
    auto image = readPng(path("a.png"), PngEncoding::Srgb, &read);
    ASSERT_TRUE(image) << image.error().message();
    EXPECT_EQ(read, sample());
    // The in-memory decoder and readImage see the same entries.
    const std::vector<std::uint8_t> bytes = fileBytes(path("a.png"));
    ImageMetadata decoded;
    ASSERT_TRUE(decodePng(bytes, "a.png", PngEncoding::Srgb, &decoded));
    EXPECT_EQ(decoded, sample());
    ImageMetadata viaReadImage;
    ASSERT_TRUE(readImage(path("a.png"), &viaReadImage));
    EXPECT_EQ(viaReadImage, sample());
    // The pixels are unchanged by the text chunks.
    auto plain = readPng(path("a.png"));
    ASSERT_TRUE(plain);
    EXPECT_EQ(*plain, *image);
}

TEST_F(ImageMetadataTest, PngStoresAsciiAsTextAndUtf8AsInternationalText) {
    ASSERT_TRUE(writePng(path("a.png"), gradient(), PngEncoding::Srgb, sample()));
    const std::vector<std::uint8_t> bytes = fileBytes(path("a.png"));
    const std::string raw(bytes.begin(), bytes.end());
    EXPECT_NE(raw.find("tEXtluxel.solver"), std::string::npos);
    EXPECT_NE(raw.find("iTXtluxel.scene"), std::string::npos);
}

TEST_F(ImageMetadataTest, ExrRoundTripKeepsEveryEntry) {
    ASSERT_TRUE(writeExr(path("a.exr"), gradient(), sample()));
    ImageMetadata read;
    auto image = readExr(path("a.exr"), &read);
    ASSERT_TRUE(image) << image.error().message();
    // The header keeps attributes sorted by name.
    EXPECT_EQ(sorted(read), sorted(sample()));
    EXPECT_EQ(*image, gradient());
    ImageMetadata decoded;
    const std::vector<std::uint8_t> bytes = fileBytes(path("a.exr"));
    ASSERT_TRUE(decodeExr(bytes, "a.exr", &decoded));
    EXPECT_EQ(sorted(decoded), sorted(sample()));
}

TEST_F(ImageMetadataTest, WriteImagesGivesEachFileItsOwnMetadata) {
    const Image image = gradient();
    const ImageMetadata a = {{"luxel.content", "fluence"}};
    const ImageMetadata b = {{"luxel.content", "display"}};
    ASSERT_TRUE(writeImages({{path("a.exr"), &image, &a}, {path("b.png"), &image, &b}}));
    ImageMetadata readA, readB;
    ASSERT_TRUE(readImage(path("a.exr"), &readA));
    ASSERT_TRUE(readImage(path("b.png"), &readB));
    EXPECT_EQ(readA, a);
    EXPECT_EQ(readB, b);
}

TEST_F(ImageMetadataTest, FilesWithoutMetadataReadAsEmpty) {
    ASSERT_TRUE(writePng(path("a.png"), gradient()));
    ASSERT_TRUE(writeExr(path("a.exr"), gradient()));
    ImageMetadata png = {{"stale", "x"}}, exr = {{"stale", "x"}};
    ASSERT_TRUE(readPng(path("a.png"), PngEncoding::Srgb, &png));
    ASSERT_TRUE(readExr(path("a.exr"), &exr));
    EXPECT_TRUE(png.empty());
    EXPECT_TRUE(exr.empty());
}

TEST_F(ImageMetadataTest, BadKeysAndValuesAreRefusedAndLeaveNoFile) {
    const std::vector<std::pair<ImageMetadata, std::string>> bad = {
        {{{"", "x"}}, "1 to 79"},
        {{{std::string(80, 'k'), "x"}}, "1 to 79"},
        {{{"a key", "x"}}, "printable ASCII"},
        {{{"k\xC3\xA4", "x"}}, "printable ASCII"},
        {{{"k", std::string("a\0b", 3)}}, "NUL"},
        {{{"k", std::string(kMaxMetadataValueBytes + 1, 'v')}}, "more than"},
        {{{"k", "1"}, {"k", "2"}}, "given twice"},
    };
    for (const auto& [metadata, needle] : bad) {
        for (const char* name : {"bad.png", "bad.exr"}) {
            const Status s = writeImage(path(name), gradient(), metadata);
            ASSERT_FALSE(s) << name << " " << needle;
            EXPECT_NE(s.error().message().find(needle), std::string::npos) << s.error().message();
            EXPECT_FALSE(fs::exists(path(name)));
        }
    }
}

TEST_F(ImageMetadataTest, ExrRefusesKeysOfItsOwnHeaderAttributes) {
    const Status s = writeExr(path("a.exr"), gradient(), {{"compression", "none"}});
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message().find("header's own attributes"), std::string::npos)
        << s.error().message();
}

TEST(ImageMetadata, FindAndSet) {
    ImageMetadata m;
    setMetadata(m, "a", "1");
    setMetadata(m, "b", "2");
    setMetadata(m, "a", "3");
    ASSERT_EQ(m.size(), 2u);
    ASSERT_NE(findMetadata(m, "a"), nullptr);
    EXPECT_EQ(*findMetadata(m, "a"), "3");
    EXPECT_EQ(findMetadata(m, "c"), nullptr);
}

TEST(ImageMetadata, Fnv1aMatchesPublishedVectors) {
    // From the FNV reference test suite (64-bit FNV-1a).
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
    EXPECT_EQ(fnv1a64Hex("a"), "af63dc4c8601ec8c");
    EXPECT_EQ(fnv1a64Hex(""), "cbf29ce484222325");
}

}  // namespace
}  // namespace luxel
