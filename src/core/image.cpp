#include "luxel/core/image.h"

#include <algorithm>

#include "luxel/core/memory.h"

namespace luxel {

Image::Image(int width, int height, int channels)
    : width_(width), height_(height), channels_(channels) {
    LUXEL_CHECK_GT(width, 0);
    LUXEL_CHECK_GT(height, 0);
    LUXEL_CHECK(channels >= 1 && channels <= 4);
    const std::size_t count = static_cast<std::size_t>(width) * height * channels;
    // Large images (a medium walked down its columns, an image written down them) on huge pages,
    // advised before the zeros first touch them.
    resizeOnHugePages(data_, count);
}

Rgb Image::rgb(int x, int y) const {
    const float* p = &data_[index(x, y)];
    if (channels_ < 3) return Rgb(p[0]);
    return {p[0], p[1], p[2]};
}

void Image::setRgb(int x, int y, Rgb value) {
    float* p = &data_[index(x, y)];
    for (int c = 0; c < std::min(channels_, 3); ++c) p[c] = value[c];
}

void Image::fill(float value) {
    std::fill(data_.begin(), data_.end(), value);
}

}  // namespace luxel
