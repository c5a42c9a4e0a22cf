// Reading a lamp room's picture pixel by pixel (the near-emitter, near-highlight and glossy-lamp
// tests): a pixel's channel sum, a region's mean, its sparkles and what a centre ray meets.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "luxel/core/image.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel::test {

inline double pixelSum(const Image& image, int x, int y) {
    return double(image.at(x, y, 0)) + image.at(x, y, 1) + image.at(x, y, 2);
}

// The mean channel sum over a set of pixels.
inline double regionMean(const Image& image, const std::vector<std::pair<int, int>>& pixels) {
    double sum = 0.0;
    for (auto [x, y] : pixels) sum += pixelSum(image, x, y);
    return sum / double(pixels.size());
}

// Pixels over k times the median of their eight neighbours (a sparkle: one pixel far brighter
// than those around it, where a lamp's reflection itself changes smoothly), and the largest such
// ratio.
struct Sparkles {
    int count = 0;
    double largest = 0.0;
};
inline Sparkles sparkles(const Image& image, const std::vector<std::pair<int, int>>& pixels,
                         double k) {
    Sparkles out;
    for (auto [x, y] : pixels) {
        std::vector<double> around;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (dx != 0 || dy != 0) around.push_back(pixelSum(image, x + dx, y + dy));
        std::nth_element(around.begin(), around.begin() + 4, around.end());
        const double ratio = pixelSum(image, x, y) / around[4];
        out.count += ratio > k;
        out.largest = std::max(out.largest, ratio);
    }
    return out;
}

// Where pixel (x, y)'s centre ray meets `room.world` (a room with `world` and shading `o`).
template <typename Room>
Hit hitAt(const Room& room, const Camera& camera, int x, int y) {
    return castToSurface(room.world, nullptr, camera.rayAt(x + 0.5, y + 0.5), room.o.stepCap).hit;
}

}  // namespace luxel::voxel::test
