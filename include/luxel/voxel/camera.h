// Perspective pinhole camera for the voxel ray caster: primary rays through pixel centres.
//
// World axes: x right, y up, z forward. Yaw 0 looks along +z and positive yaw turns towards +x;
// pitch is positive upwards and may reach +-90 (the right vector comes from yaw alone, so looking
// straight up or down is well defined). Pixel rows run top to bottom.
#pragma once

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"

namespace luxel::voxel {

// Largest accepted image side, in pixels.
inline constexpr int kMaxCameraSide = 1 << 16;

class Camera {
  public:
    // Fails for non-finite values, |pitch| > 90, a vertical field of view outside (0, 180)
    // degrees, or an image side outside 1..kMaxCameraSide.
    static Result<Camera> create(Vec3d position, double yawDegrees, double pitchDegrees,
                                 double fovYDegrees, int width, int height);
    // Looks from `position` towards `target` (which must differ). A vertical view direction keeps
    // yaw 0, so +x is right.
    static Result<Camera> lookAt(Vec3d position, Vec3d target, double fovYDegrees, int width,
                                 int height);

    // The ray through the centre of pixel (px, py); direction is unit length.
    Ray primaryRay(int px, int py) const { return rayAt(px + 0.5, py + 0.5); }
    // The ray through image position (x, y) in pixels, (0, 0) the top-left corner.
    Ray rayAt(double x, double y) const;

    Vec3d position() const { return position_; }
    Vec3d forward() const { return forward_; }
    Vec3d right() const { return right_; }
    Vec3d up() const { return up_; }
    double fovYDegrees() const { return fovY_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    Vec3d position_, forward_, right_, up_;
    double fovY_ = 60.0, tanHalf_ = 0.0;
    int width_ = 1, height_ = 1;
};

}  // namespace luxel::voxel
