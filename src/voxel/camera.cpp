// Perspective camera: validation and primary rays.
#include "luxel/voxel/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace luxel::voxel {
namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;

bool finite(const Vec3d& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

Result<Camera> Camera::create(Vec3d position, double yawDegrees, double pitchDegrees,
                              double fovYDegrees, int width, int height) {
    if (!finite(position)) return Error("camera position must be finite");
    if (!std::isfinite(yawDegrees) || !std::isfinite(pitchDegrees)) {
        return Error("camera yaw and pitch must be finite");
    }
    if (std::abs(pitchDegrees) > 90.0) {
        return Error("camera pitch must be in [-90, 90] degrees, got " +
                     std::to_string(pitchDegrees));
    }
    if (!(fovYDegrees > 0.0 && fovYDegrees < 180.0)) {
        return Error("camera vertical field of view must be in (0, 180) degrees, got " +
                     std::to_string(fovYDegrees));
    }
    if (width < 1 || height < 1 || width > kMaxCameraSide || height > kMaxCameraSide) {
        return Error("camera image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is invalid: each side must be in 1.." + std::to_string(kMaxCameraSide));
    }
    Camera camera;
    const double yaw = yawDegrees * kDegrees, pitch = pitchDegrees * kDegrees;
    camera.position_ = position;
    camera.forward_ = {std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                       std::cos(yaw) * std::cos(pitch)};
    camera.right_ = {std::cos(yaw), 0.0, -std::sin(yaw)};
    camera.up_ = cross(camera.forward_, camera.right_);
    camera.fovY_ = fovYDegrees;
    camera.tanHalf_ = std::tan(0.5 * fovYDegrees * kDegrees);
    camera.width_ = width;
    camera.height_ = height;
    return camera;
}

Result<Camera> Camera::lookAt(Vec3d position, Vec3d target, double fovYDegrees, int width,
                              int height) {
    if (!finite(position) || !finite(target))
        return Error("camera position and target must be finite");
    const Vec3d d = target - position;
    if (d == Vec3d{}) return Error("camera target must differ from its position");
    const double horizontal = std::hypot(d.x, d.z);
    const double yaw = horizontal > 0.0 ? std::atan2(d.x, d.z) : 0.0;
    // Clamped: atan2 of a vertical direction can round past 90 degrees.
    const double pitch = std::clamp(std::atan2(d.y, horizontal) / kDegrees, -90.0, 90.0);
    return create(position, yaw / kDegrees, pitch, fovYDegrees, width, height);
}

Ray Camera::rayAt(double x, double y) const {
    const double aspect = static_cast<double>(width_) / height_;
    const double sx = (2.0 * x / width_ - 1.0) * tanHalf_ * aspect;
    const double sy = (1.0 - 2.0 * y / height_) * tanHalf_;
    return {position_, normalize(forward_ + right_ * sx + up_ * sy)};
}

}  // namespace luxel::voxel
