// Pinhole projection, the inverse of the ray generation in voxel::Camera::rayAt.
#include "luxel/post/pinhole_view.h"

namespace luxel::post {

Vec3d PinholeView::direction(double x, double y) const {
    const double aspect = static_cast<double>(width) / height;
    const double sx = (2.0 * x / width - 1.0) * tanHalfFovY * aspect;
    const double sy = (1.0 - 2.0 * y / height) * tanHalfFovY;
    return forward + right * sx + up * sy;
}

bool PinholeView::project(Vec3d p, bool atInfinity, double& x, double& y) const {
    const Vec3d d = atInfinity ? p : p - position;
    const double z = dot(d, forward);
    if (!(z > 1e-9)) return false;
    const double aspect = static_cast<double>(width) / height;
    const double sx = dot(d, right) / z, sy = dot(d, up) / z;
    x = (sx / (tanHalfFovY * aspect) + 1.0) * 0.5 * width;
    y = (1.0 - sy / tanHalfFovY) * 0.5 * height;
    return true;
}

}  // namespace luxel::post
