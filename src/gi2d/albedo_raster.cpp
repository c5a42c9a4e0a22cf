// The bounce images from the scene's albedo (albedo_raster.h).
#include "gi2d/albedo_raster.h"

#include <algorithm>
#include <variant>

namespace luxel::gi2d::detail {

namespace {

// The scene with each material's albedo as its emission, kept only where `opaque` matches. The
// albedo itself is cleared, so rasterising this scene does not come back here.
Scene2D albedoScene(const Scene2D& scene, bool opaque) {
    Scene2D s = scene;
    s.boundaryRadiance = Rgb();
    s.background.emission = opaque ? Rgb() : scene.background.albedo;
    s.background.albedo = Rgb();
    for (Shape& shape : s.shapes) {
        const bool keep = shape.material.isOpaque() == opaque;
        shape.material.emission = keep ? shape.material.albedo : Rgb();
        shape.material.intensity = 1.0f;
        shape.material.albedo = Rgb();
        if (auto* layer = std::get_if<ImageLayer>(&shape.geometry)) {
            // Without an absorption image a layer's emission decides its opacity: leave it out.
            layer->emission = opaque || !layer->absorption ? nullptr : layer->albedo;
            layer->albedo = nullptr;
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

Status rasterizeAlbedo(const Scene2D& scene, const RasterOptions& options, Medium2D& medium) {
    RasterOptions albedoOptions = options;
    albedoOptions.conserveEmitterPower = false;  // albedo is a fraction, not a power
    for (bool opaque : {true, false}) {
        auto raster = rasterize(albedoScene(scene, opaque), albedoOptions);
        if (!raster) return raster.error();
        if (allZero(raster->emission)) continue;
        (opaque ? medium.reflectance : medium.scattering) =
            clampAlbedo(std::move(raster->emission));
    }
    return Ok{};
}

}  // namespace luxel::gi2d::detail
