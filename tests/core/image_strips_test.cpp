// Writers that convert strip by strip (luxel/core/image_rows.h): the files are byte for byte
// those of a whole-image write (the former path, rebuilt here from libpng and OpenEXR directly),
// they read back, and the writers never ask for more than a strip of rows at a time.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "core/image_writers.h"
#include "core/png_text.h"
#include "luxel/core/image_io.h"
#include "luxel/core/image_rows.h"
#include "luxel/core/tonemap.h"
#include "support/temp_dir.h"

namespace luxel {
namespace {

namespace fs = std::filesystem;

class ImageStrips : public test::TempDirTest {};

Image randomImage(int width, int height, int channels, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(-0.2f, 3.0f);
    Image image(width, height, channels);
    for (std::size_t i = 0; i < image.size(); ++i) image.data()[i] = dist(rng);
    return image;
}

std::string fileBytes(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Rows made on demand from `image` (not read in place), recording what the writer asks for.
struct RecordedRows {
    ImageRows rows;
    int largestRequest = 0;
    int requests = 0;
    int nextRow = 0;
    bool inOrder = true;
};

void recordFrom(const Image& image, RecordedRows& recorded) {
    recorded.rows = rowsOf(image);
    recorded.rows.image = nullptr;
    recorded.rows.read = [&image, &recorded](int y0, int y1, float* out) {
        recorded.largestRequest = std::max(recorded.largestRequest, y1 - y0);
        ++recorded.requests;
        recorded.inOrder = recorded.inOrder && y0 == recorded.nextRow && y1 > y0;
        recorded.nextRow = y1;
        rowsOf(image).read(y0, y1, out);
    };
}

// The former PNG writer: the whole image encoded to 8-bit sRGB bytes, then png_write_image.
void writeWholePng(const std::string& file, const Image& image, const ImageMetadata& metadata) {
    const int channels = image.channels();
    const int alpha = channels == 2 ? 1 : (channels == 4 ? 3 : -1);
    std::vector<png_byte> bytes(image.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const bool colour = static_cast<int>(i % channels) != alpha;
        const float v = image.data()[i];
        const float encoded = colour ? linearToSrgb(v) : (v > 0.0f ? std::min(v, 1.0f) : 0.0f);
        bytes[i] = static_cast<png_byte>(encoded * 255.0f + 0.5f);
    }
    std::vector<png_bytep> rows(static_cast<std::size_t>(image.height()));
    for (int y = 0; y < image.height(); ++y) {
        rows[y] = bytes.data() + static_cast<std::size_t>(y) * image.width() * channels;
    }
    const int types[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                         PNG_COLOR_TYPE_RGB_ALPHA};
    std::FILE* out = std::fopen(file.c_str(), "wb");
    ASSERT_NE(out, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_EQ(setjmp(png_jmpbuf(png)), 0);
    png_init_io(png, out);
    png_set_IHDR(png, info, image.width(), image.height(), 8, types[channels - 1],
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    const std::vector<png_text> text = detail::pngTextChunks(metadata);
    if (!text.empty()) png_set_text(png, info, text.data(), static_cast<int>(text.size()));
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(out);
}

// The former EXR writer: one frame buffer over the whole image, one writePixels call.
void writeWholeExr(const std::string& file, const Image& image, const ImageMetadata& metadata) {
    const char* names[] = {"R", "G", "B"};
    ASSERT_EQ(image.channels(), 3);
    Imf::Header header(image.width(), image.height());
    for (const char* name : names) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    for (const MetadataEntry& entry : metadata) {
        header.insert(entry.key, Imf::StringAttribute(entry.value));
    }
    Imf::OutputFile out(file.c_str(), header, Imf::globalThreadCount());
    const std::size_t xStride = 3 * sizeof(float);
    const std::size_t yStride = xStride * image.width();
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < 3; ++c) {
        frameBuffer.insert(names[c],
                           Imf::Slice::Make(Imf::FLOAT, image.data() + c, Imath::V2i(0, 0),
                                            image.width(), image.height(), xStride, yStride));
    }
    out.setFrameBuffer(frameBuffer);
    out.writePixels(image.height());
}

// In alphabetical order, the order an EXR header keeps.
const ImageMetadata kMetadata = {{"luxel.note", "ünïcode"}, {"luxel.scene", "strips.json"}};

TEST_F(ImageStrips, StreamedPngIsByteIdenticalToAWholeImageWrite) {
    for (const int channels : {1, 2, 3, 4}) {
        // Not a whole number of strips: the last strip is short.
        const Image image = randomImage(61, 3 * kImageStripRows + 5, channels, 7u + channels);
        RecordedRows recorded;
        recordFrom(image, recorded);
        const std::string streamed = path("streamed.png");
        ASSERT_TRUE(writeImages({{streamed, nullptr, &kMetadata, &recorded.rows}}).ok());
        const std::string whole = path("whole.png");
        writeWholePng(whole, image, kMetadata);
        EXPECT_EQ(fileBytes(streamed), fileBytes(whole)) << channels << " channels";
        // An image written from memory goes the same way.
        const std::string fromImage = path("image.png");
        ASSERT_TRUE(writePng(fromImage, image, PngEncoding::Srgb, kMetadata).ok());
        EXPECT_EQ(fileBytes(fromImage), fileBytes(whole)) << channels << " channels";

        EXPECT_LE(recorded.largestRequest, kImageStripRows);
        EXPECT_EQ(recorded.requests, 4);
        EXPECT_TRUE(recorded.inOrder);
        EXPECT_EQ(recorded.nextRow, image.height());
        ImageMetadata read;
        const Result<Image> back = readPng(streamed, PngEncoding::Srgb, &read);
        ASSERT_TRUE(back.ok()) << back.error().message();
        EXPECT_EQ(back->width(), image.width());
        EXPECT_EQ(back->channels(), channels);
        EXPECT_EQ(read, kMetadata);
    }
}

TEST_F(ImageStrips, StreamedExrIsByteIdenticalToAWholeImageWrite) {
    const int strip = detail::exrStripRows();
    EXPECT_GE(strip, 32);  // two ZIP line blocks per OpenEXR thread at least
    const Image image = randomImage(37, 2 * strip + 7, 3, 11u);
    RecordedRows recorded;
    recordFrom(image, recorded);
    const std::string streamed = path("streamed.exr");
    ASSERT_TRUE(writeImages({{streamed, nullptr, &kMetadata, &recorded.rows}}).ok());
    const std::string whole = path("whole.exr");
    writeWholeExr(whole, image, kMetadata);
    EXPECT_EQ(fileBytes(streamed), fileBytes(whole));
    const std::string fromImage = path("image.exr");
    ASSERT_TRUE(writeExr(fromImage, image, kMetadata).ok());
    EXPECT_EQ(fileBytes(fromImage), fileBytes(whole));

    EXPECT_LE(recorded.largestRequest, strip);
    EXPECT_EQ(recorded.requests, 3);
    EXPECT_TRUE(recorded.inOrder);
    ImageMetadata read;
    const Result<Image> back = readExr(streamed, &read);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(*back, image);
    EXPECT_EQ(read, kMetadata);
}

TEST_F(ImageStrips, AFailedStreamedWriteLeavesTheTargetsAsTheyWere) {
    const Image image = randomImage(8, 40, 3, 3u);
    const std::string png = path("keep.png");
    ASSERT_TRUE(writePng(png, image).ok());
    const std::string before = fileBytes(png);
    RecordedRows recorded;
    recordFrom(image, recorded);
    // The second file cannot be written: its metadata names an EXR header attribute.
    const ImageMetadata bad = {{"compression", "none"}};
    const Status s = writeImages(
        {{png, nullptr, nullptr, &recorded.rows}, {path("x.exr"), nullptr, &bad, &recorded.rows}});
    EXPECT_FALSE(s.ok());
    EXPECT_EQ(fileBytes(png), before);
    EXPECT_FALSE(fs::exists(path("x.exr")));
}

TEST_F(ImageStrips, StripStatisticsEqualTheWholeImageOnes) {
    const Image image = randomImage(50, 70, 3, 5u);
    RecordedRows recorded;
    recordFrom(image, recorded);
    for (const ToneCurve curve : {ToneCurve::Clamp, ToneCurve::Reinhard, ToneCurve::Aces}) {
        EXPECT_EQ(autoExposureStops(recorded.rows, curve), autoExposureStops(image, curve));
    }
    EXPECT_LE(recorded.largestRequest, kImageStripRows);
    const ToneMapSettings tone{0.5f, ToneCurve::Reinhard};
    const Image display = toneMap(image, tone);
    Image strip = image;
    toneMapPixels(strip.data(), strip.pixelCount(), strip.channels(), tone);
    EXPECT_EQ(strip, display);
    // Clamped, a third of the channels is at white; the light sources skip every other pixel.
    const Image clamped = toneMap(image, {0.0f, ToneCurve::Clamp});
    Image lights(50, 70, 3);
    for (int y = 0; y < 70; ++y) lights.setRgb(y % 50, y, Rgb(1.0f));
    ClippedPixels count;
    const std::size_t half = clamped.pixelCount() / 2;
    count.add(clamped.data(), 3, lights.data(), 3, half);
    count.add(clamped.data() + 3 * half, 3, lights.data() + 3 * half, 3,
              clamped.pixelCount() - half);
    EXPECT_EQ(count.fraction(), clippedFraction(clamped, &lights));
    EXPECT_EQ(count.counted, clamped.pixelCount() - 70);
    EXPECT_GT(count.fraction(), 0.3);
}

}  // namespace
}  // namespace luxel
