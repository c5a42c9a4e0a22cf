#include "commands/error_image.h"

#include <algorithm>

#include "luxel/core/tonemap.h"

namespace luxel::cli {

Image signedRelativeDifference(const Image& value, const Image& reference, double mean) {
    Image out(reference.width(), reference.height(), 1);
    const double scale = mean > 0 ? 1.0 / mean : 0.0;
    for (int y = 0; y < reference.height(); ++y) {
        for (int x = 0; x < reference.width(); ++x) {
            double d = 0;
            for (int c = 0; c < 3; ++c) d += value.at(x, y, c) - reference.at(x, y, c);
            out.at(x, y, 0) = static_cast<float>(d / 3.0 * scale);
        }
    }
    return out;
}

Image divergingColours(const Image& signedImage, double scale) {
    Image out(signedImage.width(), signedImage.height(), 3);
    for (int y = 0; y < signedImage.height(); ++y) {
        for (int x = 0; x < signedImage.width(); ++x) {
            const double t = std::clamp(signedImage.at(x, y, 0) / scale, -1.0, 1.0);
            // Linear in display (sRGB) values; stored linear like every image writePng encodes.
            const float fade = srgbToLinear(static_cast<float>(1.0 - std::abs(t)));
            out.setRgb(x, y, t >= 0 ? Rgb(1.0f, fade, fade) : Rgb(fade, fade, 1.0f));
        }
    }
    return out;
}

Image sideBySide(const std::vector<Image>& images) {
    const int gap = 4, w = images[0].width(), h = images[0].height();
    const int n = static_cast<int>(images.size());
    Image grid(n * w + (n - 1) * gap, h, 3);
    grid.fill(0.05f);
    for (int i = 0; i < n; ++i) {
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) grid.setRgb(i * (w + gap) + x, y, images[i].rgb(x, y));
        }
    }
    return grid;
}

}  // namespace luxel::cli
