// libFuzzer target for the EXR reader (luxel::decodeExr, the in-memory form of readExr): any bytes
// must give an image or an Error, never a crash, a sanitizer report or an allocation the header
// checks did not allow. A decoded image must have the promised shape (R,G,B(,A) or Y(,A)).
#include <cstddef>
#include <cstdint>
#include <span>

#include "luxel/core/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace luxel;
    const Result<Image> image = decodeExr(std::span<const std::uint8_t>(data, size), "fuzz.exr");
    if (!image) {
        if (image.error().message().empty()) __builtin_trap();  // an error says what is wrong
        return 0;
    }
    if (image->width() < 1 || image->height() < 1 || image->width() > kMaxImageSide ||
        image->height() > kMaxImageSide || image->channels() < 1 || image->channels() > 4) {
        __builtin_trap();
    }
    // Read every sample, so a short buffer would show under the address sanitizer.
    volatile float sum = 0.0f;
    for (std::size_t i = 0; i < image->size(); ++i) sum = sum + image->data()[i];
    return 0;
}
