// Shared by the image fuzz targets (PNG, EXR): what every decode must end in.
#pragma once

#include "luxel/core/image_io.h"

namespace luxel::fuzz {

// Traps unless a failed decode says what is wrong and a decoded image has a shape the readers
// promise (1 to 4 channels, each side in 1..kMaxImageSide). The image, or null after an error.
inline const Image* checkDecoded(const Result<Image>& image) {
    if (!image) {
        if (image.error().message().empty()) __builtin_trap();
        return nullptr;
    }
    if (image->width() < 1 || image->height() < 1 || image->width() > kMaxImageSide ||
        image->height() > kMaxImageSide || image->channels() < 1 || image->channels() > 4) {
        __builtin_trap();
    }
    return &*image;
}

}  // namespace luxel::fuzz
