// Host memory one finished frame needs, so commands and the viewer can refuse a size that does
// not fit before allocating any of it (luxel/core/memory.h).
#pragma once

#include <cstdint>

#include "luxel/core/image_size.h"
#include "luxel/post/post_options.h"

namespace luxel::post {

// What a GPU frame adds on the host per internal pixel: the RGBA float copy of the output
// buffer and the host-visible staging buffer it is downloaded through.
inline constexpr std::uint64_t kGpuDownloadBytesPerPixel = 32;

// An upper estimate of the host memory of one frame rendered at `internal` and finished at
// `output`: the internal RGB render, the images alive at once while `post` upscales, sharpens and
// blooms, the image written and the display image, and the 8-bit rows of a PNG encoder.
std::uint64_t finishedFrameBytes(ImageSize internal, ImageSize output, const PostOptions& post);

}  // namespace luxel::post
