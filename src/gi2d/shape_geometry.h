// Point-in-shape, signed distance and bounds for the analytic 2D shapes, in scene coordinates.
#pragma once

#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d::detail {

struct Bounds {
    double x0, y0, x1, y1;
};

Bounds shapeBounds(const Geometry& geometry);

// Exact Euclidean signed distance (negative inside) for Circle, Box, Capsule and Polygon; for an
// ImageLayer the distance to its rectangle. Rasterisation uses it to skip pixels that are surely
// inside or outside, so it must never overestimate.
double signedDistance(const Geometry& geometry, Vec2d p);

// Inside test used by the edge supersampling (the sign of signedDistance, cheaper).
bool contains(const Geometry& geometry, Vec2d p);

}  // namespace luxel::gi2d::detail
