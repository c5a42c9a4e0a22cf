// Adaptive supersampling of the voxel radiance cascades' picture
// (docs/algorithms/voxel-radiance-cascades.md §4.2): after the first pass at render.samples, the
// pixels whose luminance differs from a neighbour's by more than render.adaptive_contrast times
// the image's mean luminance (the edges of bright emitters, sparkles) are drawn again with
// render.adaptive_samples stratified rays, their mean replacing the first value. The rule is one
// function of the first pass's image, so the CPU (cascade_picture.cpp) and the GPU
// (cascade_picture_gpu.cpp, on the downloaded image) refine the same pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/image.h"
#include "luxel/voxel/shading.h"

namespace luxel::voxel::cascades {

// At most this share of the pixels is refined, those of the largest contrast first, so a picture
// full of edges (foliage, a textured wall) costs at most this share again x the samples.
inline constexpr double kAdaptiveMaxShare = 1.0 / 32.0;

// The samples a refined pixel takes: shading.adaptiveSamples (clamped to kMaxSamplesPerPixel), or
// 0 where it is off or no more than the first pass's.
int adaptiveSamples(const ShadeOptions& shading);

// The pixels (y * width + x, ascending) of an RGB `picture` that the rule refines: those whose
// Rec. 709 luminance differs from one of its 8 neighbours' by more than `contrast` x the image's
// mean luminance; above maxShare of the pixels, the largest differences (ties: the lower index).
// None in a black image. Deterministic: the same image gives the same list on any thread count.
std::vector<std::uint32_t> adaptivePixels(const Image& picture, double contrast,
                                          double maxShare = kAdaptiveMaxShare);

}  // namespace luxel::voxel::cascades
