// libFuzzer target for the PNG reader (luxel::decodePng, the in-memory form of readPng): any
// bytes must give an image or an Error, never a crash, a sanitizer report or an allocation the
// header checks did not allow. A decoded image must have the promised shape and values in [0, 1].
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include <vector>

#include <zlib.h>

#include "decoded_image.h"
#include "luxel/core/image_io.h"

namespace {

// Rewrites every complete chunk's CRC to match its content, so mutations reach the decoder instead
// of stopping at libpng's checksum test (which libpng, not luxel, owns).
void fixChunkCrcs(std::vector<std::uint8_t>& png) {
    std::size_t at = 8;  // after the signature
    while (at + 12 <= png.size()) {
        const std::uint64_t length =
            (std::uint64_t{png[at]} << 24) | (png[at + 1] << 16) | (png[at + 2] << 8) | png[at + 3];
        if (length > png.size() - at - 12) break;
        const std::size_t crcAt = at + 8 + static_cast<std::size_t>(length);
        const uLong crc = crc32(0, png.data() + at + 4, static_cast<uInt>(length + 4));
        for (int i = 0; i < 4; ++i) png[crcAt + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
        at = crcAt + 4;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* input, std::size_t size) {
    using namespace luxel;
    std::vector<std::uint8_t> bytes(input, input + size);
    fixChunkCrcs(bytes);
    const std::uint8_t* data = bytes.data();
    // Both decodings, chosen by the input length so one run needs no extra byte.
    const PngEncoding encoding = size % 2 == 0 ? PngEncoding::Srgb : PngEncoding::Linear;
    const Result<Image> image =
        decodePng(std::span<const std::uint8_t>(data, size), "fuzz.png", encoding);
    const Image* decoded = fuzz::checkDecoded(image);
    if (decoded == nullptr) return 0;
    for (std::size_t i = 0; i < decoded->size(); ++i) {
        const float v = decoded->data()[i];
        if (!(v >= 0.0f && v <= 1.0f)) __builtin_trap();  // 8/16-bit samples map into [0, 1]
    }
    return 0;
}
