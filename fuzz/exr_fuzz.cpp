// libFuzzer target for the EXR reader (luxel::decodeExr, the in-memory form of readExr): any bytes
// must give an image or an Error, never a crash, a sanitizer report or an allocation the header
// checks did not allow. A decoded image must have the promised shape (R,G,B(,A) or Y(,A)).
#include <cstddef>
#include <cstdint>
#include <span>

#include "decoded_image.h"
#include "luxel/core/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace luxel;
    const Result<Image> image = decodeExr(std::span<const std::uint8_t>(data, size), "fuzz.exr");
    const Image* decoded = fuzz::checkDecoded(image);
    if (decoded == nullptr) return 0;
    // Read every sample, so a short buffer would show under the address sanitizer.
    volatile float sum = 0.0f;
    for (std::size_t i = 0; i < decoded->size(); ++i) sum = sum + decoded->data()[i];
    return 0;
}
