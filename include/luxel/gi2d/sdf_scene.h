// Sphere tracing through a scene of opaque analytic shapes (circle, box, capsule, polygon) in empty
// space, as in the raylib radiance-cascades demo (SDF union = min). Only valid for such scenes; the
// pixel medium and its exact DDA (RayMarcher) work for everything, and give the same answer there
// up to the anti-aliased edge pixels.
#pragma once

#include <vector>

#include "luxel/core/error.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d {

class SdfScene {
  public:
    // Fails, saying why, unless every shape is analytic and opaque (absorption >= 50 in every
    // channel) and the background is empty. `width` x `height` is the render size (pixels).
    static Result<SdfScene> create(const Scene2D& scene, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    // Like RayMarcher::segment: what the segment [from, to] (pixel coordinates) sees, clipped to
    // the canvas; an opaque hit gives T = 0 and the emission of the topmost shape there.
    RaySegment segment(Vec2d from, Vec2d to, bool* leavesCanvas = nullptr) const;

    // Signed distance to the union of all shapes, in pixels (conservative when the render size
    // scales the axes differently).
    double distance(Vec2d pixel) const;

  private:
    Rgb emissionAt(Vec2d pixel) const;

    std::vector<Shape> shapes_;
    int width_ = 0, height_ = 0;
    double sx_ = 1, sy_ = 1;  // pixels per scene unit
};

}  // namespace luxel::gi2d
