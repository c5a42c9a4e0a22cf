// A float image: width x height pixels of 1 to 4 interleaved channels, rows top to bottom.
// Values are linear (no transfer curve) unless a function says otherwise.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "luxel/core/check.h"
#include "luxel/core/vec.h"

namespace luxel {

class Image {
  public:
    Image() = default;
    // A zero-filled image. Sizes must be positive and channels in 1..4 (checked).
    Image(int width, int height, int channels);

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    bool empty() const { return data_.empty(); }
    std::size_t pixelCount() const { return static_cast<std::size_t>(width_) * height_; }

    float* data() { return data_.data(); }
    const float* data() const { return data_.data(); }
    std::size_t size() const { return data_.size(); }  // number of floats

    float& at(int x, int y, int c) {
        LUXEL_DCHECK(inside(x, y) && c >= 0 && c < channels_);
        return data_[index(x, y) + c];
    }
    float at(int x, int y, int c) const {
        LUXEL_DCHECK(inside(x, y) && c >= 0 && c < channels_);
        return data_[index(x, y) + c];
    }

    // The first three channels as RGB (a 1-channel image reads as grey).
    Rgb rgb(int x, int y) const;
    // Sets the first min(3, channels) channels.
    void setRgb(int x, int y, Rgb value);

    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
    void fill(float value);

    bool operator==(const Image&) const = default;

  private:
    std::size_t index(int x, int y) const {
        return (static_cast<std::size_t>(y) * width_ + x) * channels_;
    }

    int width_ = 0, height_ = 0, channels_ = 0;
    std::vector<float> data_;
};

// Bytes an image of this size needs (for estimates before allocating).
constexpr std::uint64_t imageBytes(std::uint64_t width, std::uint64_t height, int channels) {
    return width * height * static_cast<std::uint64_t>(channels) * sizeof(float);
}

}  // namespace luxel
