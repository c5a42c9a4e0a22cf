// Upscaling a render made at a lower internal resolution: a bilinear baseline and an edge-aware
// kernel in the spirit of FSR 1 EASU (a 4 x 4 window stretched along local edges, with a
// negative lobe across them, clamped to the nearest 2 x 2 texels against ringing), optionally
// followed by contrast-limited sharpening in the spirit of RCAS. Formulas:
// src/gpu/shaders/shared/post_kernels.h; docs/algorithms/post-processing.md.
#pragma once

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/post/post_options.h"

namespace luxel::post {

// The internal size for an output size: round(side * scale), at least 1.
int internalSide(int outputSide, float scale);

Image upscaleBilinear(const Image& src, int width, int height);
Image upscaleEdge(const Image& src, int width, int height);
Image upscale(const Image& src, int width, int height, Upscaler upscaler);
// Contrast-limited sharpening, sharpness in [0, 1] (0 returns the image unchanged).
Image sharpen(const Image& src, float sharpness);

}  // namespace luxel::post
