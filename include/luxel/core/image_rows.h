// Rows of an image made on demand, so that writers and whole-image statistics can work strip by
// strip instead of on a converted copy of the whole image (a tone-mapped picture, a sum of two
// images): at 16384^2 one RGB float image is 3 GiB.
#pragma once

#include <cstddef>
#include <functional>

#include "luxel/core/image.h"

namespace luxel {

struct ImageRows {
    int width = 0, height = 0, channels = 0;
    // Writes rows [y0, y1) into `out`: width * channels floats per row, rows one after another.
    std::function<void(int y0, int y1, float* out)> read;
    // The image the rows come from unchanged, when they do: readers may then use it in place.
    const Image* image = nullptr;

    bool empty() const { return width <= 0 || height <= 0 || channels <= 0; }
    std::size_t rowFloats() const { return static_cast<std::size_t>(width) * channels; }
};

// Rows that a streaming writer or statistic asks for at a time: the buffer is this many rows, not
// the image (16 is also the line block of a ZIP-compressed EXR).
inline constexpr int kImageStripRows = 16;

// The rows of `image` as they are (the image must outlive the result).
ImageRows rowsOf(const Image& image);

// Calls fn(y0, y1, strip) for consecutive strips of at most `stripRows` rows, top to bottom, each
// read into one buffer of stripRows rows (rows.read is not called for an image read in place).
void forEachStrip(const ImageRows& rows, int stripRows,
                  const std::function<void(int y0, int y1, const float* strip)>& fn);

}  // namespace luxel
