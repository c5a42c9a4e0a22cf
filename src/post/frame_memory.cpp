// The host memory of a finished frame (see frame_memory.h): counted from what finish.cpp,
// upscale.cpp and bloom.cpp allocate.
#include "luxel/post/frame_memory.h"

#include "luxel/core/image.h"

namespace luxel::post {

std::uint64_t finishedFrameBytes(ImageSize internal, ImageSize output, const PostOptions& post) {
    const std::uint64_t rgbIn = imageBytes(internal.width, internal.height, 3);
    const std::uint64_t rgbOut = imageBytes(output.width, output.height, 3);
    std::uint64_t alive = 1;  // the finished radiance
    if (internal.width != output.width || internal.height != output.height) {
        alive += 1;  // the upscaled image
    }
    if (post.sharpness > 0.0f) alive += 2;       // an RGB copy of its input and the result
    if (post.bloom.strength > 0.0f) alive += 3;  // an RGB copy, the mip chain (1/3), the result
    const std::uint64_t written = 2 * rgbOut;    // the image written and the display image
    const std::uint64_t pngRows = rgbOut / sizeof(float);
    return rgbIn + alive * rgbOut + written + pngRows;
}

}  // namespace luxel::post
