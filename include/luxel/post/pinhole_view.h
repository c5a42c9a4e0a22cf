// A pinhole camera as the temporal upscaler sees it: the frame of luxel::voxel::Camera (x right,
// y up, rows top to bottom, vertical field of view) without the voxel module, so luxel_post does
// not depend on it. luxel/post/voxel_frames.h converts.
#pragma once

#include "luxel/core/vec.h"

namespace luxel::post {

struct PinholeView {
    Vec3d position, forward, right, up;  // unit, orthogonal
    double tanHalfFovY = 0.5773502691896257;
    int width = 1, height = 1;

    // The (unnormalised) direction through image position (x, y), (0, 0) the top-left corner:
    // forward + right * sx + up * sy, as voxel::Camera::rayAt.
    Vec3d direction(double x, double y) const;
    // Image position of a world point (w = 1) or a direction at infinity (w = 0); false when it
    // lies behind the camera.
    bool project(Vec3d p, bool atInfinity, double& x, double& y) const;
};

}  // namespace luxel::post
