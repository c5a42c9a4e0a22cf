// Which pixels of the radiance cascades' picture are drawn again (adaptive_samples.h).
#include "adaptive_samples.h"

#include <algorithm>
#include <cmath>

#include "luxel/core/parallel.h"
#include "luxel/voxel/path_trace_sums.h"
#include "luxel/voxel/render_image.h"

namespace luxel::voxel::cascades {

int adaptiveSamples(const ShadeOptions& shading) {
    const int n = std::min(shading.adaptiveSamples, kMaxSamplesPerPixel);
    return n > samplesPerPixel(shading) ? n : 0;
}

std::vector<std::uint32_t> adaptivePixels(const Image& picture, double contrast, double maxShare) {
    const int width = picture.width(), height = picture.height();
    const std::size_t count = std::size_t(width) * std::size_t(height);
    if (count == 0 || picture.channels() < 3 || !(contrast >= 0.0)) return {};
    // Luminance per pixel, a non-finite one as black, rows in parallel (the picture's other
    // thread would wait for this one); the mean summed in pixel order.
    std::vector<float> luminance(count);
    parallelForRange(height, 8, [&](int begin, int end) {
        for (std::size_t i = std::size_t(begin) * width; i < std::size_t(end) * width; ++i) {
            const float* p = picture.data() + i * std::size_t(picture.channels());
            const double y = pathLuminance(Rgb(p[0], p[1], p[2]));
            luminance[i] = std::isfinite(y) ? float(y) : 0.0f;
        }
    });
    double sum = 0.0;
    for (const float y : luminance) sum += y;
    const double mean = sum / double(count);
    if (!(mean > 0.0)) return {};
    const float threshold = float(contrast * mean);
    // The largest difference to a neighbour, rows in parallel (each pixel on its own).
    std::vector<float> difference(count, 0.0f);
    parallelForRange(height, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y)
            for (int x = 0; x < width; ++x) {
                const float here = luminance[std::size_t(y) * width + x];
                float largest = 0.0f;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                        largest = std::max(
                            largest, std::abs(here - luminance[std::size_t(ny) * width + nx]));
                    }
                difference[std::size_t(y) * width + x] = largest;
            }
    });
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < count; ++i) {
        if (difference[i] > threshold) out.push_back(std::uint32_t(i));
    }
    const std::size_t cap = std::size_t(std::max(0.0, maxShare) * double(count));
    if (out.size() > cap) {
        // The cap's largest differences: a strict order (ties by index), so one set.
        const auto larger = [&](std::uint32_t a, std::uint32_t b) {
            return difference[a] != difference[b] ? difference[a] > difference[b] : a < b;
        };
        std::nth_element(out.begin(), out.begin() + std::ptrdiff_t(cap), out.end(), larger);
        out.resize(cap);
        std::sort(out.begin(), out.end());
    }
    return out;
}

}  // namespace luxel::voxel::cascades
