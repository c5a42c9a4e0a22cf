// The sun's disk (sun_disk.h).
#include "voxel/sun_disk.h"

#include <algorithm>
#include <cmath>

namespace luxel::voxel {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The direction at 1 - cos(theta) = oneMinusCos from the axis and azimuth phi.
Vec3d coneDirection(Vec3d axis, double oneMinusCos, double phi) {
    Vec3d t, b;
    tangents(axis, t, b);
    const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    return normalize(axis * (1.0 - oneMinusCos) + t * (sinTheta * std::cos(phi)) +
                     b * (sinTheta * std::sin(phi)));
}

}  // namespace

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited".
void tangents(Vec3d n, Vec3d& t, Vec3d& b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

SunDisk SunDisk::make(Vec3 direction, double angularRadius) {
    SunDisk s;
    s.axis = normalize(Vec3d{direction.x, direction.y, direction.z});
    s.radius = std::max(angularRadius, 0.0);
    const double half = std::sin(0.5 * s.radius);
    s.oneMinusCos = 2.0 * half * half;
    s.cosRadius = 1.0 - s.oneMinusCos;
    return s;
}

bool SunDisk::contains(Vec3d direction) const {
    if (delta()) return false;
    // 1 - cos of the angle to the axis, from the chord: |d - axis|^2 / 2 (no cancellation).
    const Vec3d chord = direction - axis;
    return 0.5 * dot(chord, chord) <= oneMinusCos;
}

double SunDisk::pdf() const {
    return delta() ? 0.0 : 1.0 / (2.0 * kPi * oneMinusCos);
}

Rgb SunDisk::radiance(Rgb irradiance) const {
    if (delta()) return {};
    const double s = std::sin(radius);
    return irradiance * float(1.0 / (kPi * s * s));
}

Rgb SunDisk::radianceOverPdf(Rgb irradiance) const {
    return delta() ? irradiance : irradiance * float(2.0 / (1.0 + cosRadius));
}

Vec3d SunDisk::sample(float u0, float u1) const {
    if (delta()) return axis;
    return coneDirection(axis, double(u0) * oneMinusCos, 2.0 * kPi * double(u1));
}

Vec3d SunDisk::spiral(int i, int count) const {
    if (delta()) return axis;
    const double golden = kPi * (3.0 - std::sqrt(5.0));  // the golden angle
    const double u = (i + 0.5) / std::max(count, 1);     // area-uniform rings
    return coneDirection(axis, u * oneMinusCos, golden * i);
}

std::vector<Vec3d> spiralDirections(const SunDisk& sun, std::initializer_list<int> counts) {
    std::vector<Vec3d> out;
    for (const int count : counts) {
        const int rays = sun.delta() ? 1 : count;
        for (int i = 0; i < rays; ++i) out.push_back(sun.spiral(i, rays));
    }
    return out;
}

void SunDisk::frame(Vec3d& t, Vec3d& b) const {
    tangents(axis, t, b);
}

}  // namespace luxel::voxel
