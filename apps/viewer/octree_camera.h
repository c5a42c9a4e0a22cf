// The octree mode's camera: orbit (the WebGL octree design's drag to rotate: the camera circles a
// target point at a fixed distance) or fly (free position, as in voxel mode). Both share yaw and
// pitch, so switching keeps the view; display-free, so the math is unit-tested.
#pragma once

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/camera.h"

namespace luxel::viewer {

// Yaw 0 looks along +z, positive yaw turns towards +x, pitch is positive upwards (voxel/camera.h).
Vec3d viewDirection(double yawDegrees, double pitchDegrees);

class OrbitFlyCamera {
  public:
    // Starts from `camera` in orbit mode around `target` (the distance is the camera's to it).
    OrbitFlyCamera(const voxel::Camera& camera, Vec3d target);

    bool orbiting() const { return orbiting_; }
    // Orbit -> fly keeps the position; fly -> orbit picks the target `distance` ahead.
    void setOrbiting(bool orbit);

    // Orbit: a drag of (dx, dy) window pixels turns the camera around the target (dragging right
    // turns the scene right, as a grabbed object would); the distance stays.
    void orbitDrag(double dx, double dy);
    // Fly: mouse look, as voxel mode's right drag.
    void look(double dx, double dy);
    // Wheel notches: orbit moves towards (positive) or away from the target, a factor per notch;
    // fly moves forward a tenth of the distance per notch.
    void zoom(double notches);
    // Moves the camera (fly) or the target with it (orbit) by `offset` (world units).
    void move(Vec3d offset);
    // Orbit around `target` from where the camera is now: the view turns to face it.
    void setTarget(Vec3d target);
    void turn(double yawDegrees, double pitchDegrees);

    Vec3d position() const;
    Vec3d target() const { return target_; }
    Vec3d forward() const { return viewDirection(yaw_, pitch_); }
    Vec3d right() const;
    double yawDegrees() const { return yaw_; }
    double pitchDegrees() const { return pitch_; }
    double distance() const { return distance_; }
    double fovYDegrees() const { return fovY_; }
    Result<voxel::Camera> camera(int width, int height) const;

  private:
    bool orbiting_ = true;
    Vec3d target_;    // orbit centre
    Vec3d position_;  // fly position (orbit: derived from target, yaw, pitch and distance)
    double yaw_ = 0, pitch_ = 0, distance_ = 1, fovY_ = 60;
};

// Where to orbit a scene camera: the point of its view ray nearest the centre of `extent` (the
// look-at point of a camera aimed at the volume centre), at least a voxel ahead.
Vec3d orbitTarget(const voxel::Camera& camera, Int3 extent);

}  // namespace luxel::viewer
