// Scene rasterisation with coverage-as-opacity compositing (docs/algorithms/pixel-medium.md §1).
//
// While shapes are drawn, the absorption image holds the per-pixel opacity A = 1 - T over one pixel
// length and the emission image holds the emitted radiance L = E * A. A shape with coverage c
// replaces that fraction of the pixel:  A = (1 - c) A + c (1 - t_s),  L = (1 - c) L + c E_s (1 -
// t_s). At the end sigma = -ln(1 - A) and E = L / A. Keeping A rather than T avoids cancellation
// for faint media (1 - t_s is computed with expm1).
#include "luxel/gi2d/rasterize.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "gi2d/albedo_raster.h"
#include "gi2d/emitter_power.h"
#include "gi2d/shape_coverage.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d {
namespace {

// Opacity and emitted radiance of a material over one output pixel length.
struct PixelMaterial {
    Rgb opacity;   // 1 - exp(-sigma * l)
    Rgb radiance;  // E * opacity
};

// Absorption per output pixel: scene absorption divided by the mean scale, except opaque values,
// which stay opaque at every resolution.
float scaleAbsorption(float sigma, double meanScale) {
    if (sigma >= kOpaqueAbsorption) return sigma;
    return static_cast<float>(sigma / meanScale);
}

PixelMaterial pixelMaterial(Rgb emission, Rgb absorption, double meanScale) {
    PixelMaterial m;
    for (int c = 0; c < 3; ++c) {
        m.opacity[c] = static_cast<float>(-std::expm1(-scaleAbsorption(absorption[c], meanScale)));
        m.radiance[c] = emission[c] * m.opacity[c];
    }
    return m;
}

struct Canvas {
    Image& opacity;   // A, stored in the absorption image while drawing
    Image& radiance;  // L, stored in the emission image while drawing
    int width, height;
    detail::PixelScale scale;  // output pixels per scene pixel
    double meanScale;
};

// Blends coverage c of (opacity, radiance) into pixel (x, y).
void composite(Canvas& canvas, int x, int y, float c, Rgb opacity, Rgb radiance) {
    const Rgb a = canvas.opacity.rgb(x, y) * (1.0f - c) + opacity;
    const Rgb l = canvas.radiance.rgb(x, y) * (1.0f - c) + radiance;
    canvas.opacity.setRgb(x, y, a);
    canvas.radiance.setRgb(x, y, l);
}

// Output pixel rows/columns touched by a scene-space bounding box, clipped to the canvas.
struct PixelRange {
    int x0, y0, x1, y1;  // half-open
    bool empty() const { return x0 >= x1 || y0 >= y1; }
};

PixelRange pixelRange(const Canvas& canvas, const detail::Bounds& b) {
    auto clampTo = [](double v, int hi) {
        return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi)));
    };
    const detail::PixelScale& s = canvas.scale;
    return {clampTo(std::floor(b.x0 * s.sx) - 1, canvas.width),
            clampTo(std::floor(b.y0 * s.sy) - 1, canvas.height),
            clampTo(std::ceil(b.x1 * s.sx) + 1, canvas.width),
            clampTo(std::ceil(b.y1 * s.sy) + 1, canvas.height)};
}

void drawAnalyticShape(Canvas& canvas, const Shape& shape, const RasterOptions& options) {
    const detail::PixelScale& scale = canvas.scale;
    Rgb emission = shape.material.scaledEmission();
    if (options.conserveEmitterPower) {
        Rgb sigma;
        for (int c = 0; c < 3; ++c) {
            sigma[c] = scaleAbsorption(shape.material.absorption[c], canvas.meanScale);
        }
        emission = emission * detail::emitterPowerScale(shape, sigma, scale, options.supersample);
    }
    const PixelMaterial m = pixelMaterial(emission, shape.material.absorption, canvas.meanScale);
    const bool thinRule = shape.material.isOpaque() && emission.maxComponent() <= 0.0f;
    const PixelRange range = pixelRange(canvas, detail::shapeBounds(shape.geometry));
    if (range.empty()) return;
    parallelForRange(range.y1 - range.y0, 4, [&](int begin, int end) {
        for (int y = range.y0 + begin; y < range.y0 + end; ++y) {
            for (int x = range.x0; x < range.x1; ++x) {
                const float c = detail::drawnCoverage(shape.geometry, thinRule, scale, x, y,
                                                      options.supersample);
                if (c <= 0.0f) continue;
                composite(canvas, x, y, c, m.opacity * c, m.radiance * c);
            }
        }
    });
}

// Alpha of a texel: the last channel of grey+alpha and RGBA images, else 1.
float texelAlpha(const Image& image, int x, int y) {
    const int ch = image.channels();
    return (ch == 2 || ch == 4) ? image.at(x, y, ch - 1) : 1.0f;
}

// One sample of an image layer: its coverage and the material there.
struct LayerSample {
    float coverage = 0;
    Rgb emission, absorption;
};

LayerSample sampleLayer(const ImageLayer& layer, float intensity, Vec2d p) {
    LayerSample s;
    const double u = (p.x - layer.position.x) / layer.size.x;
    const double v = (p.y - layer.position.y) / layer.size.y;
    if (u < 0 || v < 0 || u >= 1 || v >= 1) return s;
    auto texel = [&](const Image& image) {
        return std::pair{std::min(static_cast<int>(u * image.width()), image.width() - 1),
                         std::min(static_cast<int>(v * image.height()), image.height() - 1)};
    };
    s.coverage = 1.0f;
    if (layer.emission) {
        const auto [tx, ty] = texel(*layer.emission);
        s.emission = layer.emission->rgb(tx, ty) * intensity;
        s.coverage = texelAlpha(*layer.emission, tx, ty);
    }
    if (layer.absorption) {
        const auto [tx, ty] = texel(*layer.absorption);
        s.absorption = layer.absorption->rgb(tx, ty) * layer.absorptionScale;
        if (!layer.emission) s.coverage = texelAlpha(*layer.absorption, tx, ty);
    } else if (s.emission.maxComponent() > 0.0f) {
        s.absorption =
            Rgb(kOpaqueAbsorption);  // an emission sprite: lit texels are opaque emitters
    } else {
        s.coverage = 0.0f;  // ... and dark texels leave what is below
    }
    return s;
}

void drawImageLayer(Canvas& canvas, const Shape& shape, int supersample) {
    const auto& layer = std::get<ImageLayer>(shape.geometry);
    const PixelRange range = pixelRange(canvas, detail::shapeBounds(shape.geometry));
    if (range.empty()) return;
    const int n = std::min(supersample, 4);
    const float sampleWeight = 1.0f / static_cast<float>(n * n);
    parallelForRange(range.y1 - range.y0, 4, [&](int begin, int end) {
        for (int y = range.y0 + begin; y < range.y0 + end; ++y) {
            for (int x = range.x0; x < range.x1; ++x) {
                float coverage = 0;
                Rgb opacity, radiance;
                for (int j = 0; j < n; ++j) {
                    for (int i = 0; i < n; ++i) {
                        const Vec2d p = canvas.scale.toScene(x + (i + 0.5) / n, y + (j + 0.5) / n);
                        const LayerSample s = sampleLayer(layer, shape.material.intensity, p);
                        if (s.coverage <= 0.0f) continue;
                        const PixelMaterial m =
                            pixelMaterial(s.emission, s.absorption, canvas.meanScale);
                        coverage += s.coverage * sampleWeight;
                        opacity += m.opacity * (s.coverage * sampleWeight);
                        radiance += m.radiance * (s.coverage * sampleWeight);
                    }
                }
                if (coverage > 0.0f) composite(canvas, x, y, coverage, opacity, radiance);
            }
        }
    });
}

}  // namespace

Status validateCanvasSize(int width, int height) {
    if (width <= 0 || height <= 0 || width > kMaxCanvasSide || height > kMaxCanvasSide) {
        return Error("size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is invalid: each side must be in 1.." + std::to_string(kMaxCanvasSide));
    }
    return Ok{};
}

Result<Medium2D> rasterize(const Scene2D& scene, const RasterOptions& options) {
    const bool sceneSize = options.width == 0 && options.height == 0;
    const int width = sceneSize ? scene.width : options.width;
    const int height = sceneSize ? scene.height : options.height;
    if (Status s = validateCanvasSize(width, height); !s) return s.error();
    if (Status s = validateCanvasSize(scene.width, scene.height); !s) {
        return Error("scene canvas " + s.error().message());
    }
    if (options.supersample < 1 || options.supersample > 64) {
        return Error("supersample must be in 1..64, got " + std::to_string(options.supersample));
    }
    const std::string what =
        "the " + std::to_string(width) + "x" + std::to_string(height) + " medium";
    if (Status s = checkMemory(mediumBytes(width, height), what); !s) return s.error();

    Medium2D medium{Image(width, height, 3), Image(width, height, 3), scene.boundaryRadiance};
    const double sx = static_cast<double>(width) / scene.width;
    const double sy = static_cast<double>(height) / scene.height;
    Canvas canvas{medium.absorption,          medium.emission,   width, height,
                  detail::PixelScale(sx, sy), std::sqrt(sx * sy)};

    const PixelMaterial background =
        pixelMaterial(scene.background.emission, scene.background.absorption, canvas.meanScale);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            canvas.opacity.setRgb(x, y, background.opacity);
            canvas.radiance.setRgb(x, y, background.radiance);
        }
    }
    for (const Shape& shape : scene.shapes) {
        if (std::holds_alternative<ImageLayer>(shape.geometry)) {
            drawImageLayer(canvas, shape, options.supersample);
        } else {
            drawAnalyticShape(canvas, shape, options);
        }
    }

    // Opacity/radiance back to absorption/emission.
    parallelForRange(height, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                const Rgb a = medium.absorption.rgb(x, y);
                const Rgb l = medium.emission.rgb(x, y);
                Rgb sigma, emission;
                for (int c = 0; c < 3; ++c) {
                    const float opacity = std::clamp(a[c], 0.0f, 1.0f);
                    sigma[c] =
                        std::min(static_cast<float>(-std::log1p(-static_cast<double>(opacity))),
                                 kMaxAbsorption);
                    emission[c] = opacity > 0.0f ? l[c] / opacity : 0.0f;
                }
                medium.absorption.setRgb(x, y, sigma);
                medium.emission.setRgb(x, y, emission);
            }
        }
    });
    // Light that bounces: the albedo images, rasterised by the same coverage rule.
    if (sceneBounces(scene)) {
        if (Status s = detail::rasterizeAlbedo(scene, options, medium); !s) return s.error();
    }
    return medium;
}

}  // namespace luxel::gi2d
