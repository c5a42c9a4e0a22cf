// Temporal upscaling: jittered samples, reprojected history, neighbourhood clamp, blend.
#include "luxel/post/temporal.h"

#include <algorithm>
#include <cmath>

#include "luxel/core/parallel.h"
#include "post/sample.h"

namespace luxel::post {

using detail::vec2;
using detail::vec3;

namespace {

double halton(int index, int base) {
    double f = 1.0, r = 0.0;
    for (int i = index + 1; i > 0; i /= base) {
        f /= base;
        r += f * (i % base);
    }
    return r;
}

float bilinearScalar(const Image& image, vec2 p) {
    const auto b = gpu::shared::postBilinearAt(p, image.width(), image.height());
    const float top = image.at(b.x0, b.y0, 0) * (1.0f - b.tx) + image.at(b.x1, b.y0, 0) * b.tx;
    const float bottom = image.at(b.x0, b.y1, 0) * (1.0f - b.tx) + image.at(b.x1, b.y1, 0) * b.tx;
    return top * (1.0f - b.ty) + bottom * b.ty;
}

}  // namespace

TemporalUpscaler::TemporalUpscaler(int outputWidth, int outputHeight, TemporalSettings settings)
    : width_(outputWidth),
      height_(outputHeight),
      settings_(settings),
      output_(outputWidth, outputHeight, 3),
      weight_(outputWidth, outputHeight, 1),
      history_(outputWidth, outputHeight, 3),
      historyWeight_(outputWidth, outputHeight, 1) {}

Vec2d TemporalUpscaler::jitter(int index) {
    // A cycle of 16 keeps the pattern stratified for the lengths the history weight spans.
    const int i = index % 16;
    return {halton(i, 2) - 0.5, halton(i, 3) - 0.5};
}

void TemporalUpscaler::reset() {
    frame_ = 0;
    hasHistory_ = false;
}

const Image& TemporalUpscaler::accumulate(const Image& colourIn, const Image& depth,
                                          const PinholeView& view, Vec2d frameJitter) {
    const Image colour = detail::toRgb(colourIn);
    const int w = colour.width(), h = colour.height();
    const double sx = static_cast<double>(w) / width_, sy = static_cast<double>(h) / height_;
    std::swap(history_, output_);
    std::swap(historyWeight_, weight_);
    const bool useHistory = hasHistory_;
    const float sigma2 = 2.0f * settings_.sampleSigma * settings_.sampleSigma;
    parallelForRange(height_, 4, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width_; ++x) {
                // The output pixel centre in internal pixels, and the nearest jittered sample.
                const double qx = (x + 0.5) * sx, qy = (y + 0.5) * sy;
                const int ix =
                    std::clamp(static_cast<int>(std::floor(qx - frameJitter.x)), 0, w - 1);
                const int iy =
                    std::clamp(static_cast<int>(std::floor(qy - frameJitter.y)), 0, h - 1);
                const double dx = (ix + 0.5 + frameJitter.x - qx) / sx;
                const double dy = (iy + 0.5 + frameJitter.y - qy) / sy;
                const float sampleWeight =
                    static_cast<float>(std::exp(-(dx * dx + dy * dy) / sigma2));
                const vec3 sample = detail::texel(colour, ix, iy);
                // The current frame's 3 x 3 neighbourhood bounds the history (ghosting).
                vec3 lo = sample, hi = sample;
                for (int j = -1; j <= 1; ++j) {
                    for (int i = -1; i <= 1; ++i) {
                        const vec3 c = detail::texel(colour, std::clamp(ix + i, 0, w - 1),
                                                     std::clamp(iy + j, 0, h - 1));
                        lo = min(lo, c);
                        hi = max(hi, c);
                    }
                }
                // Reprojection: the world point of this pixel at the sample's depth, seen by the
                // previous camera.
                vec3 history(0.0f);
                float historyWeight = 0.0f;
                if (useHistory) {
                    const double t = depth.at(ix, iy, 0);
                    const Vec3d dir = normalize(view.direction(x + 0.5, y + 0.5));
                    const bool sky = !std::isfinite(t);
                    const Vec3d p = sky ? dir : view.position + dir * t;
                    double px = 0, py = 0;
                    if (previous_.project(p, sky, px, py) && px >= 0 && py >= 0 && px < width_ &&
                        py < height_) {
                        const vec2 at(static_cast<float>(px), static_cast<float>(py));
                        history = min(max(detail::bilinear(history_, at), lo), hi);
                        historyWeight = bilinearScalar(historyWeight_, at);
                    }
                }
                if (historyWeight <= 0.0f) {
                    // No history: the spatial (bilinear) estimate stands in, with a small weight.
                    const vec2 q(static_cast<float>(qx - frameJitter.x),
                                 static_cast<float>(qy - frameJitter.y));
                    history = detail::bilinear(colour, q);
                    historyWeight = 0.05f;
                }
                const float total = std::min(historyWeight + sampleWeight, settings_.maxWeight);
                // The history weight is capped, so a sample always moves the pixel by at least
                // sampleWeight / (maxWeight + sampleWeight): an exponential blend.
                const float alpha = sampleWeight / (historyWeight + sampleWeight);
                detail::store(output_, x, y, history + (sample - history) * alpha);
                weight_.at(x, y, 0) = total;
            }
        }
    });
    previous_ = view;
    hasHistory_ = true;
    ++frame_;
    return output_;
}

}  // namespace luxel::post
