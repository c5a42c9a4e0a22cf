// The voxel path tracers' per-pixel running sums (the CPU's PathTracer and the GPU's
// PathTracerGpu keep the same ones, in double) and the image they make: the mean radiance, its
// standard error and the image's relative standard error
// (docs/algorithms/voxel-path-tracing.md, "Standard error").
#pragma once

#include <span>

#include "luxel/core/image.h"
#include "luxel/core/vec.h"

namespace luxel::voxel {

struct PathTraceImage {
    Image radiance;       // mean linear radiance, RGB
    Image standardError;  // standard error of that mean per pixel and channel (0 with 1 sample)
    int samplesPerPixel = 0;
    // Sum over pixels of the standard error of the mean luminance over the sum of the mean
    // luminance: the noise left, relative to the image. NaN with 1 sample or a black image.
    double relativeError = 0.0;
};

// Rec. 709 luminance of linear RGB.
inline double pathLuminance(Rgb c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// The samples of one pixel so far: sums of the values and of their squares, per channel and of
// the luminance.
struct PathPixelSums {
    double sum[3] = {0, 0, 0}, sumSquares[3] = {0, 0, 0};
    double luminance = 0, luminanceSquares = 0;

    void add(Rgb c) {
        for (int i = 0; i < 3; ++i) {
            sum[i] += c[i];
            sumSquares[i] += double(c[i]) * c[i];
        }
        const double l = pathLuminance(c);
        luminance += l;
        luminanceSquares += l * l;
    }
};

// The image of `samples` samples per pixel from the sums of width x height pixels (rows top to
// bottom).
PathTraceImage pathTraceImageOf(std::span<const PathPixelSums> sums, int width, int height,
                                int samples);

}  // namespace luxel::voxel
