// Picking and moving shapes for interactive editing.
#include "luxel/gi2d/scene2d_edit.h"

#include <type_traits>

#include "gi2d/shape_geometry.h"

namespace luxel::gi2d {

int pickShape(const Scene2D& scene, Vec2d point, double tolerance) {
    for (int i = static_cast<int>(scene.shapes.size()) - 1; i >= 0; --i) {
        const Geometry& geometry = scene.shapes[static_cast<std::size_t>(i)].geometry;
        if (detail::signedDistance(geometry, point) <= tolerance) return i;
    }
    return -1;
}

Vec2d shapeCenter(const Shape& shape) {
    const detail::Bounds b = detail::shapeBounds(shape.geometry);
    return {(b.x0 + b.x1) * 0.5, (b.y0 + b.y1) * 0.5};
}

void translateShape(Shape& shape, Vec2d delta) {
    std::visit(
        [&](auto& g) {
            using T = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<T, Circle> || std::is_same_v<T, Box>) {
                g.center = g.center + delta;
            } else if constexpr (std::is_same_v<T, Capsule>) {
                g.from = g.from + delta;
                g.to = g.to + delta;
            } else if constexpr (std::is_same_v<T, Polygon>) {
                for (Vec2d& p : g.points) p = p + delta;
            } else {
                g.position = g.position + delta;
            }
        },
        shape.geometry);
}

int brightestEmitter(const Scene2D& scene) {
    int best = -1;
    float bestLuminance = 0.0f;
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        const Rgb e = scene.shapes[i].material.scaledEmission();
        const float luminance = 0.2126f * e.r + 0.7152f * e.g + 0.0722f * e.b;
        if (luminance > 0.0f && luminance >= bestLuminance) {
            best = static_cast<int>(i);
            bestLuminance = luminance;
        }
    }
    return best;
}

}  // namespace luxel::gi2d
