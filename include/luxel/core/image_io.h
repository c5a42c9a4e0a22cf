// Reading and writing images. PNG holds 8-bit sRGB-encoded colour; EXR holds linear float. Both
// carry optional text metadata (luxel/core/image_metadata.h): EXR as string attributes, PNG as
// tEXt/iTXt chunks. Readers given a `metadata` pointer fill it with the file's text entries.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/core/image_metadata.h"
#include "luxel/core/image_rows.h"
#include "luxel/core/image_size.h"

namespace luxel {

// How 8-bit PNG values map to floats.
enum class PngEncoding {
    Srgb,    // colour: decode/encode with the sRGB transfer curve (linear floats in memory)
    Linear,  // data (masks, absorption maps): value / 255, no curve
};

// Readers refuse images larger than kMaxImageSide (image_size.h) per side, and than this in total,
// before allocating anything.
constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 28;

// Reads any PNG (grey, grey+alpha, palette, RGB, RGBA; 8 or 16 bit). The result has 1 (grey),
// 2 (grey+alpha), 3 (RGB) or 4 (RGBA) channels; alpha is always linear.
// Text chunks (tEXt, zTXt, iTXt) before and after the pixels go to `metadata`.
Result<Image> readPng(const std::string& path, PngEncoding encoding = PngEncoding::Srgb,
                      ImageMetadata* metadata = nullptr);
// The same from the bytes of a PNG file in memory; `name` is used in messages.
Result<Image> decodePng(std::span<const std::uint8_t> bytes, const std::string& name,
                        PngEncoding encoding = PngEncoding::Srgb,
                        ImageMetadata* metadata = nullptr);
// Writes 8-bit PNG with 1, 3 or 4 channels (2 is written as grey+alpha). Values are clamped to
// [0, 1] after encoding; NaN writes as 0. `metadata` (checked by checkMetadata) goes into text
// chunks before the pixels: tEXt for ASCII values, iTXt (UTF-8) for the others.
Status writePng(const std::string& path, const Image& image,
                PngEncoding encoding = PngEncoding::Srgb, const ImageMetadata& metadata = {});

// Reads an EXR as linear float: R,G,B(,A) channels (Y alone as 1 channel). The header's string
// attributes go to `metadata`.
Result<Image> readExr(const std::string& path, ImageMetadata* metadata = nullptr);
// The same from the bytes of an EXR file in memory; `name` is used in messages.
Result<Image> decodeExr(std::span<const std::uint8_t> bytes, const std::string& name,
                        ImageMetadata* metadata = nullptr);
// Writes 32-bit float EXR with channels R,G,B (3), R,G,B,A (4) or Y (1); `metadata` (checked by
// checkMetadata) becomes string attributes of the header. A key that names one of the header's
// own attributes (channels, compression, ...) is an error.
Status writeExr(const std::string& path, const Image& image, const ImageMetadata& metadata = {});

// Chooses PNG or EXR by the file extension (case-insensitive); anything else is an error.
Result<Image> readImage(const std::string& path, ImageMetadata* metadata = nullptr);
Status writeImage(const std::string& path, const Image& image, const ImageMetadata& metadata = {});

// Writes several images (each by its extension) that belong together, such as a render and its
// preview: every one goes to a temporary file first, and the targets are renamed only once all
// are complete, so a failure leaves every target as it was. Every writer converts and encodes
// strip by strip (kImageStripRows rows; an EXR several line blocks at a time), so an image given
// as `rows` is never held whole: the file is byte for byte the one its image would give.
struct ImageFile {
    std::string path;
    const Image* image = nullptr;
    const ImageMetadata* metadata = nullptr;  // none when null
    const ImageRows* rows = nullptr;          // instead of `image`: rows made on demand
};
Status writeImages(const std::vector<ImageFile>& files);

}  // namespace luxel
