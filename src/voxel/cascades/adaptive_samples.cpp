// Which pixels of the radiance cascades' picture are drawn again (adaptive_samples.h).
#include "adaptive_samples.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "luxel/core/parallel.h"
#include "luxel/voxel/path_trace_sums.h"
#include "luxel/voxel/render_image.h"

namespace luxel::voxel::cascades {

int adaptiveSamples(const ShadeOptions& shading) {
    const int n = std::min(shading.adaptiveSamples, kMaxSamplesPerPixel);
    return n > samplesPerPixel(shading) ? n : 0;
}

namespace {

// The largest difference between pixel x of row `at` and its neighbours (rows `above` and
// `below`, null at the picture's edge). The interior's columns are unrolled with no bounds test,
// so they vectorise; max is exact, so the order does not matter.
float largestDifference(const float* above, const float* at, const float* below, int width, int x) {
    const float here = at[x];
    float largest = 0.0f;
    for (const float* row : {above, at, below}) {
        if (!row) continue;
        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
            largest = std::max(largest, std::abs(here - row[nx]));
        }
    }
    return largest;
}

void rowDifferences(const float* above, const float* at, const float* below, int width,
                    float* out) {
    if (width <= 2 || !above || !below) {
        for (int x = 0; x < width; ++x) out[x] = largestDifference(above, at, below, width, x);
        return;
    }
    out[0] = largestDifference(above, at, below, width, 0);
    for (int x = 1; x < width - 1; ++x) {
        const float here = at[x];
        float largest = std::abs(here - at[x - 1]);
        largest = std::max(largest, std::abs(here - at[x + 1]));
        largest = std::max(largest, std::abs(here - above[x - 1]));
        largest = std::max(largest, std::abs(here - above[x]));
        largest = std::max(largest, std::abs(here - above[x + 1]));
        largest = std::max(largest, std::abs(here - below[x - 1]));
        largest = std::max(largest, std::abs(here - below[x]));
        out[x] = std::max(largest, std::abs(here - below[x + 1]));
    }
    out[width - 1] = largestDifference(above, at, below, width, width - 1);
}

}  // namespace

std::vector<std::uint32_t> adaptivePixels(const Image& picture, double contrast, double maxShare) {
    const int width = picture.width(), height = picture.height();
    const std::size_t count = std::size_t(width) * std::size_t(height);
    if (count == 0 || picture.channels() < 3 || !(contrast >= 0.0)) return {};
    // Luminance per pixel, a non-finite one as black, rows in parallel (the picture's other
    // thread would wait for this one; the buffer is left unset until then, so its pages are
    // first touched in parallel too); the mean summed in pixel order.
    const std::unique_ptr<float[]> luminance(new float[count]);
    parallelForRange(height, 8, [&](int begin, int end) {
        for (std::size_t i = std::size_t(begin) * width; i < std::size_t(end) * width; ++i) {
            const float* p = picture.data() + i * std::size_t(picture.channels());
            const double y = pathLuminance(Rgb(p[0], p[1], p[2]));
            luminance[i] = std::isfinite(y) ? float(y) : 0.0f;
        }
    });
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) sum += luminance[i];
    const double mean = sum / double(count);
    if (!(mean > 0.0)) return {};
    const float threshold = float(contrast * mean);
    // Each row's pixels over the threshold, with their differences, rows in parallel; joined in
    // row order, so the list ascends.
    std::vector<std::vector<std::uint32_t>> rowPixels(static_cast<std::size_t>(height));
    std::vector<std::vector<float>> rowLargest(static_cast<std::size_t>(height));
    parallelForRange(height, 8, [&](int begin, int end) {
        std::vector<float> differences(static_cast<std::size_t>(width));
        for (int y = begin; y < end; ++y) {
            const float* at = &luminance[std::size_t(y) * width];
            rowDifferences(y > 0 ? at - width : nullptr, at, y + 1 < height ? at + width : nullptr,
                           width, differences.data());
            for (int x = 0; x < width; ++x) {
                if (!(differences[std::size_t(x)] > threshold)) continue;
                rowPixels[std::size_t(y)].push_back(std::uint32_t(std::size_t(y) * width + x));
                rowLargest[std::size_t(y)].push_back(differences[std::size_t(x)]);
            }
        }
    });
    std::vector<std::uint32_t> out;
    std::vector<float> largest;
    for (int y = 0; y < height; ++y) {
        out.insert(out.end(), rowPixels[std::size_t(y)].begin(), rowPixels[std::size_t(y)].end());
        largest.insert(largest.end(), rowLargest[std::size_t(y)].begin(),
                       rowLargest[std::size_t(y)].end());
    }
    const std::size_t cap = std::size_t(std::max(0.0, maxShare) * double(count));
    if (out.size() > cap) {
        // The cap's largest differences: a strict order (ties by index), so one set.
        std::vector<std::uint32_t> order(out.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
        const auto larger = [&](std::uint32_t a, std::uint32_t b) {
            return largest[a] != largest[b] ? largest[a] > largest[b] : out[a] < out[b];
        };
        std::nth_element(order.begin(), order.begin() + std::ptrdiff_t(cap), order.end(), larger);
        order.resize(cap);
        std::vector<std::uint32_t> kept(cap);
        for (std::size_t i = 0; i < cap; ++i) kept[i] = out[order[i]];
        std::sort(kept.begin(), kept.end());
        return kept;
    }
    return out;
}

}  // namespace luxel::voxel::cascades
