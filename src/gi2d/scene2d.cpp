// Small helpers for the 2D scene model (scene2d.h).
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d {

const char* geometryTypeName(const Geometry& geometry) {
    struct Namer {
        const char* operator()(const Circle&) const { return "circle"; }
        const char* operator()(const Box&) const { return "box"; }
        const char* operator()(const Capsule&) const { return "capsule"; }
        const char* operator()(const Polygon&) const { return "polygon"; }
        const char* operator()(const ImageLayer&) const { return "image"; }
    };
    return std::visit(Namer{}, geometry);
}

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

}  // namespace luxel::gi2d
