// Bilinear and edge-aware upscaling and contrast-limited sharpening: the CPU twins of
// post_upscale (src/gpu/shaders/post/).
#include "luxel/post/upscale.h"

#include <algorithm>
#include <cmath>

#include "luxel/core/parallel.h"
#include "post/sample.h"

namespace luxel::post {

using detail::vec2;
using detail::vec3;
namespace shared = gpu::shared;
using shared::vec4;

int internalSide(int outputSide, float scale) {
    return std::max(1, static_cast<int>(std::lround(outputSide * static_cast<double>(scale))));
}

Image upscaleBilinear(const Image& source, int width, int height) {
    const Image src = detail::toRgb(source);
    Image dst(width, height, 3);
    parallelForRange(height, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                const vec2 p =
                    shared::postSourcePosition(x, y, src.width(), src.height(), width, height);
                detail::store(dst, x, y, detail::bilinear(src, p));
            }
        }
    });
    return dst;
}

namespace {

vec3 edgeSample(const Image& src, vec2 p) {
    const int w = src.width(), h = src.height();
    const float u = p.x - 0.5f, v = p.y - 0.5f;
    const int bx = static_cast<int>(std::floor(u)), by = static_cast<int>(std::floor(v));
    const vec2 f(u - std::floor(u), v - std::floor(v));
    vec3 colour[4][4];
    vec4 rows[4];
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            colour[j][i] = detail::texel(src, std::clamp(bx - 1 + i, 0, w - 1),
                                         std::clamp(by - 1 + j, 0, h - 1));
            rows[j][i] = shared::postLuma(colour[j][i]);
        }
    }
    const shared::PostEdge edge = shared::postEdgeSetup(rows[0], rows[1], rows[2], rows[3], f);
    vec3 sum(0.0f);
    float total = 0.0f;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            const float weight =
                shared::postEdgeWeight(edge, vec2(float(i - 1) - f.x, float(j - 1) - f.y));
            sum += colour[j][i] * weight;
            total += weight;
        }
    }
    // Deringing: the result stays within the nearest 2 x 2 texels (as EASU does).
    const vec3 lo = min(min(colour[1][1], colour[1][2]), min(colour[2][1], colour[2][2]));
    const vec3 hi = max(max(colour[1][1], colour[1][2]), max(colour[2][1], colour[2][2]));
    const vec3 value = sum * (1.0f / std::max(total, 1e-6f));
    return min(max(value, lo), hi);
}

}  // namespace

Image upscaleEdge(const Image& source, int width, int height) {
    const Image src = detail::toRgb(source);
    Image dst(width, height, 3);
    parallelForRange(height, 4, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                const vec2 p =
                    shared::postSourcePosition(x, y, src.width(), src.height(), width, height);
                detail::store(dst, x, y, edgeSample(src, p));
            }
        }
    });
    return dst;
}

Image upscale(const Image& src, int width, int height, Upscaler upscaler) {
    if (src.width() == width && src.height() == height) return detail::toRgb(src);
    return upscaler == Upscaler::Bilinear ? upscaleBilinear(src, width, height)
                                          : upscaleEdge(src, width, height);
}

Image sharpen(const Image& source, float sharpness) {
    const Image src = detail::toRgb(source);
    if (!(sharpness > 0.0f)) return src;
    const int w = src.width(), h = src.height();
    Image dst(w, h, 3);
    parallelForRange(h, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                const auto at = [&](int dx, int dy) {
                    return detail::texel(src, std::clamp(x + dx, 0, w - 1),
                                         std::clamp(y + dy, 0, h - 1));
                };
                detail::store(dst, x, y,
                              shared::postSharpen(at(0, 0), at(0, -1), at(0, 1), at(1, 0),
                                                  at(-1, 0), std::min(sharpness, 1.0f)));
            }
        }
    });
    return dst;
}

}  // namespace luxel::post
