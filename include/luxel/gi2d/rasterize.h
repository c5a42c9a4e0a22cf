// Scene -> medium: shapes rasterised with anti-aliased coverage using the coverage-as-opacity rule
// of docs/algorithms/pixel-medium.md §1, so partially covered edge pixels of opaque emitters keep
// their full radiance.
#pragma once

#include <cstdint>

#include "luxel/core/error.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d {

struct RasterOptions {
    // Output size in pixels; 0x0 = the scene's canvas. A different size scales the scene (each axis
    // by its own factor) and divides absorption by the mean scale so optical depths stay the same;
    // opaque materials stay opaque per pixel.
    int width = 0, height = 0;
    // Samples per pixel side on shape edges (n x n). Interior and exterior pixels are found exactly
    // from the shape's distance field and need no samples. Image layers use min(n, 4).
    int supersample = 16;
    // Scale each analytic emitter's emission so that its rasterisation emits the exact shape's
    // power at any size and sub-pixel position (docs/algorithms/pixel-medium.md §4). Off only
    // where the "emission" rasterised is not light (the albedo images).
    bool conserveEmitterPower = true;
};

// Largest accepted canvas side, in pixels.
inline constexpr int kMaxCanvasSide = 65536;

// A scene with any albedo (sceneBounces) also gets Medium2D::scattering and ::reflectance.
// Fails for absurd sizes (<= 0 or > kMaxCanvasSide) or when the medium would not fit in memory.
Result<Medium2D> rasterize(const Scene2D& scene, const RasterOptions& options = {});

// Validates an output size and says how large it is ("render size 0x100 is invalid: ...").
Status validateCanvasSize(int width, int height);

}  // namespace luxel::gi2d
