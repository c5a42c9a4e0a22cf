// Tests for PNG/EXR reading and writing: round trips, encodings, and bad files.
#include "luxel/core/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "luxel/core/tonemap.h"
#include "support/temp_dir.h"

namespace luxel {
namespace {

namespace fs = std::filesystem;

// Small PNG files that the writer never produces, made with Python's zlib (filter 0 rows).
// 2x1 palette: opaque red, then blue with tRNS alpha 128.
const unsigned char kPalettePng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
    0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x03, 0x00, 0x00, 0x00, 0xc3,
    0xfc, 0x8f, 0xb8, 0x00, 0x00, 0x00, 0x06, 0x50, 0x4c, 0x54, 0x45, 0xff, 0x00, 0x00, 0x00,
    0x00, 0xff, 0x6c, 0xa1, 0xfd, 0x8e, 0x00, 0x00, 0x00, 0x02, 0x74, 0x52, 0x4e, 0x53, 0xff,
    0x80, 0x08, 0x0f, 0xb3, 0x6a, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c,
    0x63, 0x60, 0x60, 0x04, 0x00, 0x00, 0x04, 0x00, 0x02, 0xbf, 0x7a, 0x3f, 0x4a, 0x00, 0x00,
    0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 2x1 16-bit RGB: (65535, 0, 32768), (1000, 2000, 3000).
const unsigned char kRgb16Png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x10, 0x02, 0x00, 0x00, 0x00, 0x2b, 0xd0, 0x34,
    0x9e, 0x00, 0x00, 0x00, 0x15, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xff, 0x9f, 0x81,
    0xa1, 0x81, 0x81, 0xf9, 0x05, 0xfb, 0x05, 0xee, 0x1d, 0x00, 0x22, 0xea, 0x05, 0x04, 0x26, 0xb8,
    0x91, 0x44, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 1x1 16-bit grey+alpha: (13107 = 0.2, 65535).
const unsigned char kGreyAlpha16Png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x10, 0x04, 0x00, 0x00,
    0x00, 0xe5, 0x8c, 0xd0, 0x41, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x30, 0x36, 0xfe, 0xff, 0x1f, 0x00, 0x04, 0x67, 0x02, 0x65, 0x70, 0x78,
    0xa4, 0x76, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 8x1 1-bit grey: 10110000.
const unsigned char kGrey1BitPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x01, 0x01, 0x00, 0x00, 0x00,
    0x00, 0xcb, 0x7b, 0xd2, 0xee, 0x00, 0x00, 0x00, 0x0a, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0xd8, 0x00, 0x00, 0x00, 0xb2, 0x00, 0xb1, 0x55, 0x0a, 0xe8, 0x2a, 0x00,
    0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 3x3 8-bit grey, Adam7 interlaced: value 10 * (y * 3 + x).
const unsigned char kInterlacedPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x03, 0x08, 0x00, 0x00, 0x00, 0x01, 0x04, 0x44, 0xda,
    0xf5, 0x00, 0x00, 0x00, 0x17, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0x60, 0x10, 0x61,
    0xb0, 0x09, 0x60, 0xe0, 0x62, 0x70, 0x63, 0x90, 0xd3, 0x30, 0x02, 0x00, 0x08, 0xa7, 0x01, 0x69,
    0x3d, 0xdf, 0x97, 0x62, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// Headers only (a token IDAT): 100000x1, and 60000x60000.
const unsigned char kTooWidePng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x01, 0x86, 0xa0, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0x78, 0x15, 0x49,
    0x09, 0x00, 0x00, 0x00, 0x04, 0x49, 0x44, 0x41, 0x54, 0x00, 0x00, 0x00, 0x00, 0xea, 0x23, 0xe7,
    0x07, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
const unsigned char kTooManyPixelsPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0xea, 0x60, 0x00, 0x00, 0xea, 0x60, 0x08, 0x00, 0x00, 0x00, 0x00, 0xa5, 0xb9, 0x2a,
    0x9e, 0x00, 0x00, 0x00, 0x04, 0x49, 0x44, 0x41, 0x54, 0x00, 0x00, 0x00, 0x00, 0xea, 0x23, 0xe7,
    0x07, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};

constexpr float kHalfStep = 0.5f / 255.0f;

class ImageIoTest : public test::TempDirTest {
  protected:
    std::string writeBytes(const std::string& name, const void* data, std::size_t size) const {
        const std::string file = path(name);
        std::ofstream out(file, std::ios::binary);
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
        return file;
    }
};

Image randomImage(int width, int height, int channels, float lo, float hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(lo, hi);
    Image image(width, height, channels);
    for (std::size_t i = 0; i < image.size(); ++i) image.data()[i] = dist(rng);
    return image;
}

bool isAlpha(int channels, int c) {
    return (channels == 2 && c == 1) || (channels == 4 && c == 3);
}

void expectSameShape(const Image& a, const Image& b) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    EXPECT_EQ(a.channels(), b.channels());
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST_F(ImageIoTest, PngSrgbRoundTripWithinQuantisation) {
    for (int channels : {1, 2, 3, 4}) {
        SCOPED_TRACE(channels);
        const Image image = randomImage(7, 5, channels, 0.0f, 1.0f, 10 + channels);
        const std::string file = path("srgb" + std::to_string(channels) + ".png");
        ASSERT_TRUE(writePng(file, image).ok());
        const Result<Image> read = readPng(file);
        ASSERT_TRUE(read.ok()) << read.error().message();
        expectSameShape(*read, image);
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                for (int c = 0; c < channels; ++c) {
                    const float want = image.at(x, y, c);
                    const float got = read->at(x, y, c);
                    // Colour is quantised in the encoded domain; alpha is stored linearly.
                    if (isAlpha(channels, c)) {
                        EXPECT_NEAR(got, want, kHalfStep + 1e-6f);
                    } else {
                        EXPECT_NEAR(linearToSrgb(got), linearToSrgb(want), kHalfStep + 1e-5f);
                    }
                }
            }
        }
    }
}

TEST_F(ImageIoTest, PngLinearRoundTripWithinQuantisation) {
    for (int channels : {1, 3, 4}) {
        SCOPED_TRACE(channels);
        const Image image = randomImage(6, 4, channels, 0.0f, 1.0f, 20 + channels);
        const std::string file = path("linear" + std::to_string(channels) + ".png");
        ASSERT_TRUE(writePng(file, image, PngEncoding::Linear).ok());
        const Result<Image> read = readPng(file, PngEncoding::Linear);
        ASSERT_TRUE(read.ok()) << read.error().message();
        expectSameShape(*read, image);
        for (std::size_t i = 0; i < image.size(); ++i) {
            EXPECT_NEAR(read->data()[i], image.data()[i], kHalfStep + 1e-6f);
        }
    }
}

TEST_F(ImageIoTest, PngLinearRoundTripOfQuantisedValuesIsExact) {
    Image image(256, 1, 1);
    for (int v = 0; v < 256; ++v) image.at(v, 0, 0) = static_cast<float>(v) / 255.0f;
    const std::string file = path("ramp.png");
    ASSERT_TRUE(writePng(file, image, PngEncoding::Linear).ok());
    const Result<Image> read = readPng(file, PngEncoding::Linear);
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_EQ(*read, image);
}

TEST_F(ImageIoTest, PngSrgbAndLinearEncodingsStoreDifferentBytes) {
    Image image(1, 1, 3);
    image.fill(0.5f);
    const std::string srgbFile = path("srgb.png");
    const std::string linearFile = path("linear.png");
    ASSERT_TRUE(writePng(srgbFile, image, PngEncoding::Srgb).ok());
    ASSERT_TRUE(writePng(linearFile, image, PngEncoding::Linear).ok());

    // Linear 0.5 encodes to sRGB 0.7354 -> byte 188; stored linearly it is byte 128.
    const Result<Image> srgbBytes = readPng(srgbFile, PngEncoding::Linear);
    const Result<Image> linearBytes = readPng(linearFile, PngEncoding::Linear);
    ASSERT_TRUE(srgbBytes.ok() && linearBytes.ok());
    EXPECT_FLOAT_EQ(srgbBytes->at(0, 0, 0), 188.0f / 255.0f);
    EXPECT_FLOAT_EQ(linearBytes->at(0, 0, 0), 128.0f / 255.0f);

    const Result<Image> decoded = readPng(srgbFile, PngEncoding::Srgb);
    ASSERT_TRUE(decoded.ok());
    EXPECT_NEAR(decoded->at(0, 0, 1), 0.5f, 0.003f);
}

TEST_F(ImageIoTest, PngAlphaIsLinearUnderSrgbEncoding) {
    Image image(1, 1, 4);
    image.at(0, 0, 0) = 0.5f;
    image.at(0, 0, 3) = 0.5f;
    const std::string file = path("alpha.png");
    ASSERT_TRUE(writePng(file, image).ok());
    const Result<Image> raw = readPng(file, PngEncoding::Linear);
    ASSERT_TRUE(raw.ok());
    EXPECT_FLOAT_EQ(raw->at(0, 0, 0), 188.0f / 255.0f);
    EXPECT_FLOAT_EQ(raw->at(0, 0, 3), 128.0f / 255.0f);
}

TEST_F(ImageIoTest, PngClampsOutOfRangeValuesAndWritesNanAsZero) {
    Image image(5, 1, 1);
    const float values[] = {-1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity(), 0.25f};
    for (int x = 0; x < 5; ++x) image.at(x, 0, 0) = values[x];
    for (PngEncoding encoding : {PngEncoding::Srgb, PngEncoding::Linear}) {
        const std::string file = path("clamp.png");
        ASSERT_TRUE(writePng(file, image, encoding).ok());
        const Result<Image> read = readPng(file, encoding);
        ASSERT_TRUE(read.ok());
        EXPECT_EQ(read->at(0, 0, 0), 0.0f);
        EXPECT_EQ(read->at(1, 0, 0), 1.0f);
        EXPECT_EQ(read->at(2, 0, 0), 0.0f);
        EXPECT_EQ(read->at(3, 0, 0), 1.0f);
        EXPECT_NEAR(read->at(4, 0, 0), 0.25f, 0.01f);
    }
}

TEST_F(ImageIoTest, PngReadsPaletteWithTransparencyAsRgba) {
    const std::string file = writeBytes("palette.png", kPalettePng, sizeof kPalettePng);
    const Result<Image> read = readPng(file);
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_EQ(read->channels(), 4);
    ASSERT_EQ(read->width(), 2);
    EXPECT_EQ(read->rgb(0, 0), Rgb(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(read->at(0, 0, 3), 1.0f);
    EXPECT_EQ(read->rgb(1, 0), Rgb(0.0f, 0.0f, 1.0f));
    EXPECT_FLOAT_EQ(read->at(1, 0, 3), 128.0f / 255.0f);
}

TEST_F(ImageIoTest, PngReadsSixteenBitSamples) {
    const std::string rgb = writeBytes("rgb16.png", kRgb16Png, sizeof kRgb16Png);
    const Result<Image> read = readPng(rgb, PngEncoding::Linear);
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_EQ(read->channels(), 3);
    const float want[] = {65535, 0, 32768, 1000, 2000, 3000};
    for (int i = 0; i < 6; ++i) EXPECT_FLOAT_EQ(read->data()[i], want[i] / 65535.0f);

    const std::string greyAlpha = writeBytes("ga16.png", kGreyAlpha16Png, sizeof kGreyAlpha16Png);
    const Result<Image> ga = readPng(greyAlpha, PngEncoding::Srgb);
    ASSERT_TRUE(ga.ok()) << ga.error().message();
    ASSERT_EQ(ga->channels(), 2);
    EXPECT_FLOAT_EQ(ga->at(0, 0, 0), srgbToLinear(0.2f));
    EXPECT_EQ(ga->at(0, 0, 1), 1.0f);
}

TEST_F(ImageIoTest, PngReadsOneBitGrey) {
    const std::string file = writeBytes("grey1.png", kGrey1BitPng, sizeof kGrey1BitPng);
    const Result<Image> read = readPng(file);
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_EQ(read->channels(), 1);
    ASSERT_EQ(read->width(), 8);
    const float want[] = {1, 0, 1, 1, 0, 0, 0, 0};
    for (int x = 0; x < 8; ++x) EXPECT_EQ(read->at(x, 0, 0), want[x]) << x;
}

TEST_F(ImageIoTest, PngReadsInterlaced) {
    const std::string file = writeBytes("adam7.png", kInterlacedPng, sizeof kInterlacedPng);
    const Result<Image> read = readPng(file, PngEncoding::Linear);
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_EQ(read->width(), 3);
    ASSERT_EQ(read->height(), 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 3; ++x) {
            EXPECT_FLOAT_EQ(read->at(x, y, 0), 10.0f * (y * 3 + x) / 255.0f) << x << "," << y;
        }
    }
}

TEST_F(ImageIoTest, ExrRoundTripIsExactIncludingHdrValues) {
    for (int channels : {1, 2, 3, 4}) {
        SCOPED_TRACE(channels);
        Image image = randomImage(9, 7, channels, -2.0f, 50.0f, 30 + channels);
        // Values a half-float file or a clamp would change.
        image.data()[0] = 12345.678f;
        image.data()[1] = 1.0e-7f;
        image.data()[2] = 1.0e30f;
        image.data()[3] = 0.0f;
        const std::string file = path("hdr" + std::to_string(channels) + ".exr");
        ASSERT_TRUE(writeExr(file, image).ok());
        const Result<Image> read = readExr(file);
        ASSERT_TRUE(read.ok()) << read.error().message();
        expectSameShape(*read, image);
        EXPECT_EQ(*read, image);
    }
}

TEST_F(ImageIoTest, ReadAndWriteImageChooseTheFormatByExtension) {
    Image image = randomImage(4, 3, 3, 0.0f, 4.0f, 40);
    image.at(0, 0, 0) = 3.5f;

    const std::string exr = path("image.EXR");
    ASSERT_TRUE(writeImage(exr, image).ok());
    const Result<Image> exrRead = readImage(exr);
    ASSERT_TRUE(exrRead.ok()) << exrRead.error().message();
    EXPECT_EQ(*exrRead, image);  // exact, so it was not a PNG

    const std::string png = path("image.Png");
    ASSERT_TRUE(writeImage(png, image).ok());
    std::ifstream in(png, std::ios::binary);
    std::vector<unsigned char> head(4);
    in.read(reinterpret_cast<char*>(head.data()), 4);
    EXPECT_EQ(head, (std::vector<unsigned char>{0x89, 'P', 'N', 'G'}));
    const Result<Image> pngRead = readImage(png);
    ASSERT_TRUE(pngRead.ok()) << pngRead.error().message();
    EXPECT_EQ(pngRead->at(0, 0, 0), 1.0f);  // clamped: 8-bit sRGB
}

TEST_F(ImageIoTest, UnknownExtensionIsAnError) {
    const Image image(2, 2, 3);
    for (const std::string name : {"image.jpg", "image", "image.png.bak"}) {
        const std::string file = path(name);
        const Status written = writeImage(file, image);
        ASSERT_FALSE(written.ok());
        EXPECT_TRUE(contains(written.error().message(), file)) << written.error().message();
        EXPECT_TRUE(contains(written.error().message(), ".png")) << written.error().message();
        EXPECT_TRUE(contains(written.error().message(), ".exr")) << written.error().message();
        EXPECT_FALSE(fs::exists(file));

        const Result<Image> read = readImage(file);
        ASSERT_FALSE(read.ok());
        EXPECT_TRUE(contains(read.error().message(), file)) << read.error().message();
    }
}

TEST_F(ImageIoTest, MissingFileErrorNamesThePath) {
    for (const std::string name : {"missing.png", "missing.exr"}) {
        const std::string file = path(name);
        const std::string expected = "cannot open '" + file + "': No such file or directory";
        const Result<Image> viaImage = readImage(file);
        ASSERT_FALSE(viaImage.ok());
        EXPECT_EQ(viaImage.error().message(), expected);
    }
    const Result<Image> png = readPng(path("missing.png"));
    ASSERT_FALSE(png.ok());
    EXPECT_TRUE(contains(png.error().message(), path("missing.png")));
    const Result<Image> exr = readExr(path("missing.exr"));
    ASSERT_FALSE(exr.ok());
    EXPECT_TRUE(contains(exr.error().message(), path("missing.exr")));
}

TEST_F(ImageIoTest, TruncatedPngIsAnError) {
    const std::string good = path("good.png");
    ASSERT_TRUE(writePng(good, randomImage(32, 32, 4, 0.0f, 1.0f, 50)).ok());
    const auto size = fs::file_size(good);
    // Inside the signature, inside IHDR, inside the pixel data, and just short of IEND's CRC.
    for (std::uintmax_t keep : {std::uintmax_t{4}, std::uintmax_t{8}, std::uintmax_t{20},
                                std::uintmax_t{40}, size / 2, size - 12, size - 1}) {
        SCOPED_TRACE(keep);
        const std::string cut = path("cut.png");
        fs::copy_file(good, cut, fs::copy_options::overwrite_existing);
        fs::resize_file(cut, keep);
        const Result<Image> read = readPng(cut);
        ASSERT_FALSE(read.ok());
        EXPECT_TRUE(contains(read.error().message(), cut)) << read.error().message();
    }
}

TEST_F(ImageIoTest, TruncatedExrIsAnError) {
    const std::string good = path("good.exr");
    ASSERT_TRUE(writeExr(good, randomImage(64, 64, 4, 0.0f, 10.0f, 60)).ok());
    const auto size = fs::file_size(good);
    for (std::uintmax_t keep :
         {std::uintmax_t{0}, std::uintmax_t{4}, std::uintmax_t{100}, size / 2, size - 1}) {
        SCOPED_TRACE(keep);
        const std::string cut = path("cut.exr");
        fs::copy_file(good, cut, fs::copy_options::overwrite_existing);
        fs::resize_file(cut, keep);
        const Result<Image> read = readExr(cut);
        ASSERT_FALSE(read.ok());
        EXPECT_TRUE(contains(read.error().message(), cut)) << read.error().message();
    }
}

TEST_F(ImageIoTest, GarbageFilesAreErrors) {
    std::mt19937 rng(70);
    std::vector<unsigned char> garbage(4096);
    for (unsigned char& byte : garbage) byte = static_cast<unsigned char>(rng());
    for (const std::string name : {"garbage.png", "garbage.exr"}) {
        const std::string file = writeBytes(name, garbage.data(), garbage.size());
        const Result<Image> read = readImage(file);
        ASSERT_FALSE(read.ok()) << name;
        EXPECT_TRUE(contains(read.error().message(), file)) << read.error().message();
    }
    // A valid signature followed by garbage gets past the first check.
    std::vector<unsigned char> withSignature(kPalettePng, kPalettePng + 8);
    withSignature.insert(withSignature.end(), garbage.begin(), garbage.end());
    const Result<Image> png =
        readPng(writeBytes("signed.png", withSignature.data(), withSignature.size()));
    EXPECT_FALSE(png.ok());
    // Same for the EXR magic number and version.
    std::vector<unsigned char> exrMagic = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    exrMagic.insert(exrMagic.end(), garbage.begin(), garbage.end());
    const Result<Image> exr = readExr(writeBytes("magic.exr", exrMagic.data(), exrMagic.size()));
    EXPECT_FALSE(exr.ok());
}

TEST_F(ImageIoTest, AbsurdPngDimensionsAreRejected) {
    const Result<Image> wide = readPng(writeBytes("wide.png", kTooWidePng, sizeof kTooWidePng));
    ASSERT_FALSE(wide.ok());
    EXPECT_TRUE(contains(wide.error().message(), "width")) << wide.error().message();
    const Result<Image> many =
        readPng(writeBytes("many.png", kTooManyPixelsPng, sizeof kTooManyPixelsPng));
    ASSERT_FALSE(many.ok());
    EXPECT_TRUE(contains(many.error().message(), "too large")) << many.error().message();
}

// Found by fuzz/png_fuzz.cpp: a 69-byte PNG declaring 16384x16384 RGBA at 16 bits (within the
// size limits) made the reader allocate and zero 2 GiB of rows before libpng found that the data
// was missing. No deflate stream that short can hold such an image, so it is refused up front.
const unsigned char kHugeButShortPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0x40, 0x00, 0x10, 0x06, 0x00, 0x00,
    0x00, 0xf9, 0x58, 0xcc, 0xc7, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x60, 0xa0, 0x0c, 0x00, 0x00, 0x00, 0x40, 0x00, 0x01, 0xb7, 0x34, 0x7c,
    0xef, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};

TEST_F(ImageIoTest, PngTooShortForItsDeclaredSizeIsRefusedBeforeDecoding) {
    const std::string file = writeBytes("short.png", kHugeButShortPng, sizeof kHugeButShortPng);
    const Result<Image> read = readPng(file);
    ASSERT_FALSE(read.ok());
    EXPECT_TRUE(contains(read.error().message(),
                         "the header declares 16384x16384 pixels (2.0 GiB of pixel data), "
                         "which a file of 69 bytes cannot hold"))
        << read.error().message();
    const Result<Image> decoded = decodePng(
        std::span<const std::uint8_t>(kHugeButShortPng, sizeof kHugeButShortPng), "short.png");
    ASSERT_FALSE(decoded.ok());
    EXPECT_TRUE(contains(decoded.error().message(), "cannot hold")) << decoded.error().message();
}

// A scanline EXR header (one FLOAT "Y" channel, no compression) and a one-entry offset table.
std::vector<unsigned char> exrHeader(int width, int height) {
    std::vector<unsigned char> out = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    const auto i32 = [&](std::int32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
    };
    const auto str = [&](const std::string& s) { out.insert(out.end(), s.begin(), s.end() + 1); };
    const auto attribute = [&](const std::string& name, const std::string& type, int size) {
        str(name);
        str(type);
        i32(size);
    };
    const float one = 1.0f;
    std::int32_t oneBits;
    std::memcpy(&oneBits, &one, 4);
    attribute("channels", "chlist", 19);
    str("Y");
    i32(2);  // FLOAT
    i32(0);  // pLinear + reserved
    i32(1);
    i32(1);
    out.push_back(0);
    attribute("compression", "compression", 1);
    out.push_back(0);
    for (const char* window : {"dataWindow", "displayWindow"}) {
        attribute(window, "box2i", 16);
        i32(0);
        i32(0);
        i32(width - 1);
        i32(height - 1);
    }
    attribute("lineOrder", "lineOrder", 1);
    out.push_back(0);
    attribute("pixelAspectRatio", "float", 4);
    i32(oneBits);
    attribute("screenWindowCenter", "v2f", 8);
    i32(0);
    i32(0);
    attribute("screenWindowWidth", "float", 4);
    i32(oneBits);
    out.push_back(0);
    const std::int32_t tableEnd = static_cast<std::int32_t>(out.size()) + 8;
    i32(tableEnd);
    i32(0);
    return out;
}

TEST_F(ImageIoTest, AbsurdExrDimensionsAreRejected) {
    const std::vector<unsigned char> header = exrHeader(100000, 1);
    const Result<Image> read = readExr(writeBytes("wide.exr", header.data(), header.size()));
    ASSERT_FALSE(read.ok());
    EXPECT_TRUE(contains(read.error().message(), "too large")) << read.error().message();
}

// Found by fuzz/exr_fuzz.cpp: 24 bytes whose first attribute declares a value of 1.9 GB. OpenEXR
// allocated that much before finding the file too short (about 0.3 s per read under the address
// sanitizer). The header pass refuses such a size first, naming the attribute.
TEST_F(ImageIoTest, ExrAttributeLargerThanTheFileIsRefusedBeforeOpenExrReadsIt) {
    const unsigned char bytes[] = {0x76, 0x2f, 0x31, 0x01, 0x02, 0x02, 0x00, 0x00,
                                   0x0b, 0x6a, 0x61, 0x6e, 0x6e, 0x65, 0x6c, 0x73,
                                   0x00, 0x63, 0x00, 0x00, 0x76, 0xd9, 0x76, 0xcf};
    const Result<Image> read = readExr(writeBytes("attribute.exr", bytes, sizeof bytes));
    ASSERT_FALSE(read.ok());
    EXPECT_TRUE(contains(read.error().message(),
                         "attribute '?jannels' declares 1993963008 bytes, but only 1 are left"))
        << read.error().message();
    const Result<Image> decoded =
        decodeExr(std::span<const std::uint8_t>(bytes, sizeof bytes), "attribute.exr");
    ASSERT_FALSE(decoded.ok());
    EXPECT_TRUE(contains(decoded.error().message(), "declares 1993963008 bytes"))
        << decoded.error().message();
}

TEST_F(ImageIoTest, WritingIntoAMissingDirectoryIsAnError) {
    const Image image(2, 2, 3);
    for (const std::string name : {"no/such/dir/out.png", "no/such/dir/out.exr"}) {
        const std::string file = path(name);
        const Status written = writeImage(file, image);
        ASSERT_FALSE(written.ok());
        EXPECT_TRUE(contains(written.error().message(), file)) << written.error().message();
    }
}

TEST_F(ImageIoTest, WritingAnEmptyImageIsAnError) {
    EXPECT_FALSE(writePng(path("empty.png"), Image()).ok());
    EXPECT_FALSE(writeExr(path("empty.exr"), Image()).ok());
}

}  // namespace
}  // namespace luxel
