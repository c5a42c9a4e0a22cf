// Rows of an image made on demand (luxel/core/image_rows.h).
#include "luxel/core/image_rows.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace luxel {

ImageRows rowsOf(const Image& image) {
    ImageRows rows;
    rows.width = image.width();
    rows.height = image.height();
    rows.channels = image.channels();
    rows.image = &image;
    const std::size_t rowFloats = rows.rowFloats();
    rows.read = [&image, rowFloats](int y0, int y1, float* out) {
        std::memcpy(out, image.data() + static_cast<std::size_t>(y0) * rowFloats,
                    static_cast<std::size_t>(y1 - y0) * rowFloats * sizeof(float));
    };
    return rows;
}

void forEachStrip(const ImageRows& rows, int stripRows,
                  const std::function<void(int y0, int y1, const float* strip)>& fn) {
    if (rows.empty()) return;
    LUXEL_CHECK(stripRows > 0);
    const std::size_t rowFloats = rows.rowFloats();
    std::vector<float> strip;
    if (rows.image == nullptr) {
        strip.resize(static_cast<std::size_t>(std::min(stripRows, rows.height)) * rowFloats);
    }
    for (int y0 = 0; y0 < rows.height; y0 += stripRows) {
        const int y1 = std::min(rows.height, y0 + stripRows);
        if (rows.image != nullptr) {
            fn(y0, y1, rows.image->data() + static_cast<std::size_t>(y0) * rowFloats);
        } else {
            rows.read(y0, y1, strip.data());
            fn(y0, y1, strip.data());
        }
    }
}

}  // namespace luxel
