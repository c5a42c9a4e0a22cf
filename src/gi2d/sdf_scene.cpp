// Sphere tracing of opaque analytic shapes.
#include "luxel/gi2d/sdf_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gi2d/shape_geometry.h"

namespace luxel::gi2d {
namespace {
constexpr double kHitDistance = 1e-3;  // pixels
constexpr double kMinStep = 1e-3;      // pixels; keeps grazing rays moving
constexpr int kMaxSteps = 512;
}  // namespace

Result<SdfScene> SdfScene::create(const Scene2D& scene, int width, int height) {
    if (scene.background.absorption.maxComponent() > 0.0f ||
        scene.background.emission.maxComponent() > 0.0f) {
        return Error("SDF tracing needs an empty background (this scene has a medium)");
    }
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        const Shape& s = scene.shapes[i];
        if (std::holds_alternative<ImageLayer>(s.geometry)) {
            return Error("SDF tracing cannot trace image layers (" + s.name + ")");
        }
        if (s.material.absorption.minComponent() < kOpaqueAbsorption) {
            return Error("SDF tracing needs opaque shapes; " + s.name + " is not");
        }
    }
    SdfScene out;
    out.shapes_ = scene.shapes;
    out.width_ = width;
    out.height_ = height;
    out.sx_ = static_cast<double>(width) / scene.width;
    out.sy_ = static_cast<double>(height) / scene.height;
    return out;
}

double SdfScene::distance(Vec2d pixel) const {
    const Vec2d p{pixel.x / sx_, pixel.y / sy_};
    double d = std::numeric_limits<double>::infinity();
    for (const Shape& s : shapes_) d = std::min(d, detail::signedDistance(s.geometry, p));
    return d * std::min(sx_, sy_);
}

Rgb SdfScene::emissionAt(Vec2d pixel) const {
    // The last drawn shape at the point wins (draw order = depth order).
    const Vec2d p{pixel.x / sx_, pixel.y / sy_};
    const double slack = kHitDistance * 2 / std::min(sx_, sy_);
    for (auto it = shapes_.rbegin(); it != shapes_.rend(); ++it) {
        if (detail::signedDistance(it->geometry, p) <= slack) return it->material.scaledEmission();
    }
    return {};
}

RaySegment SdfScene::segment(Vec2d from, Vec2d to, bool* leavesCanvas) const {
    auto outside = [&](Vec2d p) { return p.x < 0 || p.y < 0 || p.x > width_ || p.y > height_; };
    if (leavesCanvas) *leavesCanvas = outside(to);
    const Vec2d delta = to - from;
    const double len = length(delta);
    if (len <= 0.0) return {};
    const Vec2d dir = delta / len;
    double t = 0.0;
    for (int step = 0; step < kMaxSteps && t < len; ++step) {
        const Vec2d p = from + dir * t;
        const double d = distance(p);
        if (d < kHitDistance) {
            // Hits outside the canvas do not count: the medium ends at the canvas border.
            if (outside(p)) return {};
            return {emissionAt(p), Rgb(0.0f)};
        }
        t += std::max(d, kMinStep);
    }
    return {};
}

}  // namespace luxel::gi2d
