// Analytic geometry of circles, boxes, capsules and polygons (Quilez-style exact distance fields).
#include "gi2d/shape_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace luxel::gi2d::detail {
namespace {

template <typename... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <typename... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

// The point in the box's own frame (centre at 0, axes along the box sides).
Vec2d toBoxFrame(const Box& box, Vec2d p) {
    const double a = box.angleDegrees * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    const Vec2d d = p - box.center;
    return {c * d.x + s * d.y, -s * d.x + c * d.y};
}

double boxDistance(const Box& box, Vec2d p) {
    const Vec2d local = toBoxFrame(box, p);
    const double qx = std::abs(local.x) - box.size.x * 0.5;
    const double qy = std::abs(local.y) - box.size.y * 0.5;
    const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
    return outside + std::min(std::max(qx, qy), 0.0);
}

double segmentDistance(Vec2d a, Vec2d b, Vec2d p) {
    const Vec2d ab = b - a, ap = p - a;
    const double len2 = dot(ab, ab);
    const double h = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
    return length(ap - ab * h);
}

// Even-odd rule: count crossings of a ray towards +x.
bool polygonContains(const Polygon& polygon, Vec2d p) {
    bool inside = false;
    const auto& v = polygon.points;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        if ((v[i].y > p.y) != (v[j].y > p.y)) {
            const double x = v[j].x + (p.y - v[j].y) * (v[i].x - v[j].x) / (v[i].y - v[j].y);
            if (p.x < x) inside = !inside;
        }
    }
    return inside;
}

double polygonDistance(const Polygon& polygon, Vec2d p) {
    double d = std::numeric_limits<double>::infinity();
    const auto& v = polygon.points;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        d = std::min(d, segmentDistance(v[j], v[i], p));
    }
    return polygonContains(polygon, p) ? -d : d;
}

Box layerRectangle(const ImageLayer& layer) {
    return Box{layer.position + layer.size * 0.5, layer.size, 0.0};
}

}  // namespace

Bounds shapeBounds(const Geometry& geometry) {
    return std::visit(
        Overloaded{
            [](const Circle& c) {
                return Bounds{c.center.x - c.radius, c.center.y - c.radius, c.center.x + c.radius,
                              c.center.y + c.radius};
            },
            [](const Box& b) {
                const double a = b.angleDegrees * std::numbers::pi / 180.0;
                const double c = std::abs(std::cos(a)), s = std::abs(std::sin(a));
                const double hx = 0.5 * (b.size.x * c + b.size.y * s);
                const double hy = 0.5 * (b.size.x * s + b.size.y * c);
                return Bounds{b.center.x - hx, b.center.y - hy, b.center.x + hx, b.center.y + hy};
            },
            [](const Capsule& c) {
                const double r = c.thickness * 0.5;
                return Bounds{std::min(c.from.x, c.to.x) - r, std::min(c.from.y, c.to.y) - r,
                              std::max(c.from.x, c.to.x) + r, std::max(c.from.y, c.to.y) + r};
            },
            [](const Polygon& poly) {
                Bounds b{poly.points[0].x, poly.points[0].y, poly.points[0].x, poly.points[0].y};
                for (const Vec2d& v : poly.points) {
                    b = {std::min(b.x0, v.x), std::min(b.y0, v.y), std::max(b.x1, v.x),
                         std::max(b.y1, v.y)};
                }
                return b;
            },
            [](const ImageLayer& l) {
                return Bounds{l.position.x, l.position.y, l.position.x + l.size.x,
                              l.position.y + l.size.y};
            },
        },
        geometry);
}

double signedDistance(const Geometry& geometry, Vec2d p) {
    return std::visit(
        Overloaded{
            [&](const Circle& c) { return length(p - c.center) - c.radius; },
            [&](const Box& b) { return boxDistance(b, p); },
            [&](const Capsule& c) { return segmentDistance(c.from, c.to, p) - c.thickness * 0.5; },
            [&](const Polygon& poly) { return polygonDistance(poly, p); },
            [&](const ImageLayer& l) { return boxDistance(layerRectangle(l), p); },
        },
        geometry);
}

bool contains(const Geometry& geometry, Vec2d p) {
    if (const auto* polygon = std::get_if<Polygon>(&geometry)) return polygonContains(*polygon, p);
    return signedDistance(geometry, p) < 0.0;
}

}  // namespace luxel::gi2d::detail
