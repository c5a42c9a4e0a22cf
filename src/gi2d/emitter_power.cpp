// Exact and rasterised power of an emitter over one set of lines (emitter_power.h).
#include "gi2d/emitter_power.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "luxel/core/parallel.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d::detail {
namespace {

// Directions over half a turn. One shape over vacuum has one emission E in every pixel it touches,
// so the radiance along a line is E (1 - T) whichever way it is read: the half turn opposite
// gives the same powers, and the total is twice this half.
constexpr int kDirections = 32;
constexpr int kMaxOffsets = 2048;              // lines per direction at most
constexpr double kFinestSpacing = 1.0 / 32.0;  // output pixels between lines, at best
constexpr int kMaxTraceSteps = 4096;

// The output pixels around a shape: its bounding box with 2 pixels of vacuum on each side.
struct Window {
    int x0, y0, width, height;
};

Window windowAround(const Geometry& geometry, const PixelScale& scale) {
    const Bounds b = shapeBounds(geometry);
    const int x0 = static_cast<int>(std::floor(b.x0 * scale.sx)) - 2;
    const int y0 = static_cast<int>(std::floor(b.y0 * scale.sy)) - 2;
    const int x1 = static_cast<int>(std::ceil(b.x1 * scale.sx)) + 2;
    const int y1 = static_cast<int>(std::ceil(b.y1 * scale.sy)) + 2;
    return {x0, y0, x1 - x0, y1 - y0};
}

// The shape alone rasterised into the window by the rule of docs/algorithms/pixel-medium.md §1
// (emitters get no §5 gain): a pixel of coverage c transmits 1 - c (1 - t) and emits E there
// (L / A = E for one shape over vacuum).
Medium2D rasterAlone(const Geometry& geometry, Rgb emission, Rgb sigma, const PixelScale& scale,
                     int supersample, const Window& w) {
    Medium2D m{Image(w.width, w.height, 3), Image(w.width, w.height, 3), Rgb()};
    Rgb opacity;
    for (int c = 0; c < 3; ++c) opacity[c] = static_cast<float>(-std::expm1(-sigma[c]));
    for (int y = 0; y < w.height; ++y) {
        for (int x = 0; x < w.width; ++x) {
            const float cov = pixelCoverage(geometry, scale, w.x0 + x, w.y0 + y, supersample);
            if (cov <= 0.0f) continue;
            Rgb s, e;
            for (int c = 0; c < 3; ++c) {
                const double a = cov * opacity[c];
                s[c] = std::min(static_cast<float>(-std::log1p(-a)), kMaxAbsorption);
                e[c] = a > 0 ? emission[c] : 0.0f;
            }
            m.absorption.setRgb(x, y, s);
            m.emission.setRgb(x, y, e);
        }
    }
    return m;
}

// The fraction of the segment a -> b (scene coordinates) inside the box.
double boxChord(const Box& box, Vec2d a, Vec2d b) {
    const double angle = box.angleDegrees * std::numbers::pi / 180.0;
    const double c = std::cos(angle), s = std::sin(angle);
    auto local = [&](Vec2d p) {
        const Vec2d d = p - box.center;
        return Vec2d{c * d.x + s * d.y, -s * d.x + c * d.y};
    };
    const Vec2d p = local(a), q = local(b), d = q - p;
    double t0 = 0.0, t1 = 1.0;
    const double half[2] = {0.5 * box.size.x, 0.5 * box.size.y};
    const double start[2] = {p.x, p.y}, step[2] = {d.x, d.y};
    for (int axis = 0; axis < 2; ++axis) {
        if (step[axis] == 0.0) {
            if (std::abs(start[axis]) > half[axis]) return 0.0;
            continue;
        }
        double enter = (-half[axis] - start[axis]) / step[axis];
        double leave = (half[axis] - start[axis]) / step[axis];
        if (enter > leave) std::swap(enter, leave);
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
    }
    return std::max(0.0, t1 - t0);
}

// Radiance the exact shape sends to `from` along the segment from -> to (window coordinates):
// the inside intervals found by sphere tracing the distance field, composited front to back.
Rgb exactRadiance(const Geometry& geometry, Rgb emission, Rgb sigma, const PixelScale& scale,
                  const Window& w, Vec2d from, Vec2d to) {
    const Vec2d delta = to - from;
    const double len = length(delta);
    const Vec2d dir = delta / len;
    // A circle under a uniform scale: one chord, 2 sqrt(r^2 - h^2) at distance h from the centre.
    if (const auto* circle = std::get_if<Circle>(&geometry); circle && scale.sx == scale.sy) {
        const Vec2d centre{circle->center.x * scale.sx - w.x0, circle->center.y * scale.sy - w.y0};
        const double r = circle->radius * scale.sx;
        const Vec2d rel = centre - from;
        const double h = std::abs(dir.x * rel.y - dir.y * rel.x);
        if (h >= r) return Rgb();
        const double chord = 2 * std::sqrt(r * r - h * h);
        Rgb radiance;
        for (int c = 0; c < 3; ++c) {
            radiance[c] = emission[c] * static_cast<float>(-std::expm1(-sigma[c] * chord));
        }
        return radiance;
    }
    // A box: one chord, the segment's part between both pairs of slabs in the box's frame. The
    // parameter along the segment is the same in scene and output pixels (an affine map), so this
    // holds for any scale.
    if (const auto* box = std::get_if<Box>(&geometry)) {
        const double chord = boxChord(*box, scale.toScene(w.x0 + from.x, w.y0 + from.y),
                                      scale.toScene(w.x0 + to.x, w.y0 + to.y)) *
                             len;
        Rgb radiance;
        for (int c = 0; c < 3; ++c) {
            radiance[c] = emission[c] * static_cast<float>(-std::expm1(-sigma[c] * chord));
        }
        return radiance;
    }
    // A distance in scene units is at least this many output pixels.
    const double minScale = std::min(scale.sx, scale.sy);
    Rgb radiance, transmittance(1.0f);
    double t = 0, inside = 0;
    auto flush = [&] {
        if (inside <= 0) return;
        for (int c = 0; c < 3; ++c) {
            const float tr = static_cast<float>(std::exp(-sigma[c] * inside));
            radiance[c] += transmittance[c] * emission[c] * (1.0f - tr);
            transmittance[c] *= tr;
        }
        inside = 0;
    };
    for (int step = 0; step < kMaxTraceSteps && t < len; ++step) {
        const Vec2d p = from + dir * t;
        const double d = signedDistance(geometry, scale.toScene(w.x0 + p.x, w.y0 + p.y));
        const double advance = std::min(std::max(std::abs(d) * minScale, 1e-3), len - t);
        if (d < 0) {
            inside += advance;
        } else {
            flush();
        }
        t += advance;
    }
    flush();
    return radiance;
}

// The shape's thickness in output pixels: exact for circles, boxes and capsules; for polygons twice
// the largest depth inside over 4 x 4 points per window pixel, or the first value found at or above
// kNoPowerThickness (thicker gets no factor either way). It must not depend on where the shape lies
// on the pixel grid, or the factor would change as a shape moves.
double shapeThickness(const Geometry& geometry, const PixelScale& scale, const Window& w) {
    const double toOutput = std::min(scale.sx, scale.sy);
    if (const auto* c = std::get_if<Circle>(&geometry)) return 2 * c->radius * toOutput;
    if (const auto* b = std::get_if<Box>(&geometry))
        return std::min(b->size.x, b->size.y) * toOutput;
    if (const auto* c = std::get_if<Capsule>(&geometry)) return c->thickness * toOutput;
    double deepest = 0;
    for (int y = 0; y < 4 * w.height; ++y) {
        for (int x = 0; x < 4 * w.width; ++x) {
            const Vec2d p = scale.toScene(w.x0 + (x + 0.5) / 4, w.y0 + (y + 0.5) / 4);
            deepest = std::max(deepest, -signedDistance(geometry, p) * toOutput);
            if (2 * deepest >= kNoPowerThickness) return 2 * deepest;
        }
    }
    return 2 * deepest;
}

}  // namespace

EmitterPower emitterPower(const Geometry& geometry, Rgb emission, Rgb sigma,
                          const PixelScale& scale, int supersample) {
    const Window w = windowAround(geometry, scale);
    const Medium2D alone = rasterAlone(geometry, emission, sigma, scale, supersample, w);
    const RayMarcher marcher(alone);
    const Vec2d centre{0.5 * w.width, 0.5 * w.height};
    const double reach = 0.5 * std::hypot(w.width, w.height) + 1.0;
    const int offsets =
        std::clamp(static_cast<int>(std::ceil(2 * reach / kFinestSpacing)), 1, kMaxOffsets);
    const double spacing = 2 * reach / offsets;

    std::vector<EmitterPower> perDirection(kDirections);
    parallelForRange(kDirections, 1, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const double theta = std::numbers::pi * k / kDirections;
            const Vec2d u{std::cos(theta), std::sin(theta)}, v{-u.y, u.x};
            // A different fraction of the spacing per direction, so that the edges of the exact
            // shape are not always sampled at the same phase.
            const double jitter = std::fmod(0.5 + k * 0.6180339887498949, 1.0);
            EmitterPower sum;
            for (int i = 0; i < offsets; ++i) {
                const double s = -reach + (i + jitter) * spacing;
                const Vec2d from = centre + v * s - u * reach, to = centre + v * s + u * reach;
                sum.raster += marcher.segment(from, to).radiance;
                sum.exact += exactRadiance(geometry, emission, sigma, scale, w, from, to);
            }
            perDirection[k] = sum;
        }
    });
    EmitterPower total;
    for (const EmitterPower& p : perDirection) {
        total.exact += p.exact;
        total.raster += p.raster;
    }
    const float measure = static_cast<float>(2 * spacing * std::numbers::pi / kDirections);
    total.exact = total.exact * measure;
    total.raster = total.raster * measure;
    return total;
}

Rgb emitterPowerScale(const Shape& shape, Rgb sigma, const PixelScale& scale, int supersample) {
    const Rgb emission = shape.material.scaledEmission();
    if (emission.maxComponent() <= 0.0f || std::holds_alternative<ImageLayer>(shape.geometry)) {
        return Rgb(1.0f);
    }
    const Window w = windowAround(shape.geometry, scale);
    if (static_cast<long>(w.width) * w.height > kMaxPowerPixels) return Rgb(1.0f);
    // Full factor up to kFullPowerThickness, none from kNoPowerThickness: thick emitters keep the
    // radiance E along every line that sees their inside (inside a closed emissive ring every pixel
    // reads E), at the price of their rim.
    const double thickness = shapeThickness(shape.geometry, scale, w);
    if (thickness >= kNoPowerThickness) return Rgb(1.0f);
    const float weight = static_cast<float>(std::clamp(
        (kNoPowerThickness - thickness) / (kNoPowerThickness - kFullPowerThickness), 0.0, 1.0));
    // The ratio does not depend on the emission's size; unit emission keeps channels that do not
    // emit measurable.
    const EmitterPower p = emitterPower(shape.geometry, Rgb(1.0f), sigma, scale, supersample);
    Rgb factor(1.0f);
    for (int c = 0; c < 3; ++c) {
        if (emission[c] > 0.0f && p.raster[c] > 0.0f && p.exact[c] > 0.0f) {
            factor[c] = 1.0f + weight * (p.exact[c] / p.raster[c] - 1.0f);
        }
    }
    return factor;
}

}  // namespace luxel::gi2d::detail
