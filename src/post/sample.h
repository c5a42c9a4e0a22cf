// Pixel access for the CPU twins of the post passes: clamp-to-edge bilinear reads of RGB images
// through the shared footprint (gpu/shaders/shared/post_kernels.h).
#pragma once

#include "gpu/shaders/shared/post_kernels.h"
#include "luxel/core/image.h"

namespace luxel::post::detail {

using gpu::shared::vec2;
using gpu::shared::vec3;

inline vec3 texel(const Image& image, int x, int y) {
    const float* p = image.data() + (static_cast<std::size_t>(y) * image.width() + x) * 3;
    return vec3(p[0], p[1], p[2]);
}

inline void store(Image& image, int x, int y, vec3 c) {
    float* p = image.data() + (static_cast<std::size_t>(y) * image.width() + x) * 3;
    p[0] = c.x;
    p[1] = c.y;
    p[2] = c.z;
}

inline vec3 bilinear(const Image& image, vec2 p) {
    const auto b = gpu::shared::postBilinearAt(p, image.width(), image.height());
    const vec3 top = texel(image, b.x0, b.y0) * (1.0f - b.tx) + texel(image, b.x1, b.y0) * b.tx;
    const vec3 bottom = texel(image, b.x0, b.y1) * (1.0f - b.tx) + texel(image, b.x1, b.y1) * b.tx;
    return top * (1.0f - b.ty) + bottom * b.ty;
}

// An RGB copy (post passes work on 3 channels).
Image toRgb(const Image& image);

}  // namespace luxel::post::detail
