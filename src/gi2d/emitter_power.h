// Emitters that keep their exact power when rasterised (docs/algorithms/pixel-medium.md §4).
//
// An emitter's power is the integral over every directed line of the radiance it sends along that
// line. Coverage as opacity (§1) gets it wrong at sub-pixel scale: a disk of radius 0.35 px loses
// about half, one of radius 1.5 px gains 14-28%. The rasteriser therefore measures both powers on
// the same set of lines, the exact shape's from its distance field and the rasterised shape's
// through its pixels, and scales a thin emitter's emission by their ratio. One factor per shape
// keeps its light where it was drawn and changes smoothly as it moves.
#pragma once

#include "gi2d/shape_coverage.h"
#include "luxel/core/vec.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d::detail {

// Emitters up to this thick (output pixels, twice the largest depth inside) get the full factor;
// from kNoPowerThickness on none, linearly in between.
inline constexpr double kFullPowerThickness = 3.0;
inline constexpr double kNoPowerThickness = 6.0;

// Shapes whose padded bounding box covers more output pixels than this keep their emission: their
// rim excess is below 0.5% (about 0.5 px over the radius) and the estimate would cost more.
inline constexpr long kMaxPowerPixels = 256L * 256L;

// Per channel, in output pixel units: the power of the exact shape and of its rasterisation alone
// (vacuum around it), for emission `emission` and absorption `sigma` per output pixel.
struct EmitterPower {
    Rgb exact, raster;
};
EmitterPower emitterPower(const Geometry& geometry, Rgb emission, Rgb sigma,
                          const PixelScale& scale, int supersample);

// exact / raster per channel: the factor for the shape's emission, faded out between
// kFullPowerThickness and kNoPowerThickness; 1 where a channel does not emit, for image layers
// (already per pixel) and for shapes above kMaxPowerPixels.
Rgb emitterPowerScale(const Shape& shape, Rgb sigma, const PixelScale& scale, int supersample);

}  // namespace luxel::gi2d::detail
