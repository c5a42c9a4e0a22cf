// Interim fill of the bounce images from the scene's albedo (see bounce_fill.h).
#include "luxel/gi2d/bounce_fill.h"

#include <algorithm>
#include <variant>

namespace luxel::gi2d {

bool sceneBounces(const Scene2D& scene) {
    if (scene.background.albedo != Rgb()) return true;
    for (const Shape& s : scene.shapes) {
        if (s.material.albedo != Rgb()) return true;
        if (const auto* layer = std::get_if<ImageLayer>(&s.geometry); layer && layer->albedo) {
            return true;
        }
    }
    return false;
}

namespace {

// The scene with each material's albedo as its emission, kept only where `opaque` matches.
Scene2D albedoScene(const Scene2D& scene, bool opaque) {
    Scene2D s = scene;
    s.boundaryRadiance = Rgb();
    s.background.emission = opaque ? Rgb() : scene.background.albedo;
    for (Shape& shape : s.shapes) {
        const bool keep = shape.material.isOpaque() == opaque;
        shape.material.emission = keep ? shape.material.albedo : Rgb();
        shape.material.intensity = 1.0f;
        if (auto* layer = std::get_if<ImageLayer>(&shape.geometry)) {
            // Without an absorption image a layer's emission decides its opacity: leave it out.
            layer->emission = opaque || !layer->absorption ? nullptr : layer->albedo;
        }
    }
    return s;
}

bool allZero(const Image& image) {
    for (std::size_t i = 0; i < image.size(); ++i) {
        if (image.data()[i] != 0.0f) return false;
    }
    return true;
}

// Albedo stays below 1 whatever the coverage blend did.
Image clampAlbedo(Image image) {
    for (std::size_t i = 0; i < image.size(); ++i) {
        image.data()[i] = std::min(std::max(image.data()[i], 0.0f), 0.999f);
    }
    return image;
}

}  // namespace

Status fillBounceImages(const Scene2D& scene, const RasterOptions& options, Medium2D& medium) {
    if (medium.bounces() || !sceneBounces(scene)) return Ok{};
    for (bool opaque : {true, false}) {
        auto raster = rasterize(albedoScene(scene, opaque), options);
        if (!raster) return raster.error();
        if (allZero(raster->emission)) continue;
        (opaque ? medium.reflectance : medium.scattering) =
            clampAlbedo(std::move(raster->emission));
    }
    return Ok{};
}

}  // namespace luxel::gi2d
