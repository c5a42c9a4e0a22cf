// Orbit and fly camera math for octree mode.
#include "octree_camera.h"

#include <algorithm>
#include <cmath>

namespace luxel::viewer {
namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;
constexpr double kOrbitDegreesPerPixel = 0.3;
constexpr double kLookDegreesPerPixel = 0.2;  // as voxel mode
constexpr double kZoomPerNotch = 0.85;
constexpr double kMinDistance = 0.5;  // voxels
// Just short of straight up or down: the orbit keeps a defined right vector and never flips.
constexpr double kMaxPitch = 89.0;

double wrapDegrees(double d) {
    return std::fmod(std::fmod(d + 180.0, 360.0) + 360.0, 360.0) - 180.0;
}

}  // namespace

Vec3d viewDirection(double yawDegrees, double pitchDegrees) {
    const double yaw = yawDegrees * kDegrees, pitch = pitchDegrees * kDegrees;
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

OrbitFlyCamera::OrbitFlyCamera(const voxel::Camera& camera, Vec3d target)
    : orbiting_(false), position_(camera.position()), fovY_(camera.fovYDegrees()) {
    setTarget(target);
    orbiting_ = true;  // the derived position is the camera's: target - forward * distance
}

void OrbitFlyCamera::setTarget(Vec3d target) {
    const Vec3d from = position();
    Vec3d d = target - from;
    distance_ = std::max(length(d), kMinDistance);
    if (length(d) < kMinDistance) d = forward();  // too close to aim: keep looking the same way
    d = normalize(d);
    yaw_ = std::atan2(d.x, d.z) / kDegrees;
    pitch_ = std::clamp(std::asin(std::clamp(d.y, -1.0, 1.0)) / kDegrees, -kMaxPitch, kMaxPitch);
    target_ = target;
    if (orbiting_) position_ = target_ - forward() * distance_;
}

void OrbitFlyCamera::setOrbiting(bool orbit) {
    if (orbit == orbiting_) return;
    if (orbit) {
        target_ = position_ + forward() * distance_;
    } else {
        position_ = position();
    }
    orbiting_ = orbit;
}

Vec3d OrbitFlyCamera::position() const {
    return orbiting_ ? target_ - forward() * distance_ : position_;
}

Vec3d OrbitFlyCamera::right() const {
    const double yaw = yaw_ * kDegrees;
    return {std::cos(yaw), 0.0, -std::sin(yaw)};
}

void OrbitFlyCamera::turn(double yawDegrees, double pitchDegrees) {
    yaw_ = wrapDegrees(yaw_ + yawDegrees);
    pitch_ = std::clamp(pitch_ + pitchDegrees, -kMaxPitch, kMaxPitch);
}

void OrbitFlyCamera::orbitDrag(double dx, double dy) {
    // The camera moves opposite to the drag so the scene follows the pointer; dragging down
    // raises the camera to look down on the scene.
    turn(-dx * kOrbitDegreesPerPixel, -dy * kOrbitDegreesPerPixel);
}

void OrbitFlyCamera::look(double dx, double dy) {
    turn(dx * kLookDegreesPerPixel, -dy * kLookDegreesPerPixel);
}

void OrbitFlyCamera::zoom(double notches) {
    if (orbiting_) {
        distance_ = std::max(distance_ * std::pow(kZoomPerNotch, notches), kMinDistance);
    } else {
        position_ = position_ + forward() * (0.1 * distance_ * notches);
    }
}

void OrbitFlyCamera::move(Vec3d offset) {
    if (orbiting_) {
        target_ = target_ + offset;
    } else {
        position_ = position_ + offset;
    }
}

Result<voxel::Camera> OrbitFlyCamera::camera(int width, int height) const {
    return voxel::Camera::create(position(), yaw_, pitch_, fovY_, width, height);
}

Vec3d orbitTarget(const voxel::Camera& camera, Int3 extent) {
    const Vec3d centre{extent.x * 0.5, extent.y * 0.5, extent.z * 0.5};
    const double along = std::max(dot(centre - camera.position(), camera.forward()), 1.0);
    return camera.position() + camera.forward() * along;
}

}  // namespace luxel::viewer
