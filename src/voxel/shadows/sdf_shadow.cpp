// The CPU march of the SDF soft shadow around the shared step (soft_shadow.h).
#include "luxel/voxel/shadows/sdf_shadow.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gpu/shaders/shared/soft_shadow.h"

namespace luxel::voxel {
namespace sh = gpu::shared;

namespace {

// Past a cell boundary by this much, so the next sample lies in the next cell.
constexpr double kCrossing = 1e-3;

// t at which the ray leaves the box [0, size] (0 if it starts outside going away).
double exitT(Int3 size, Vec3d o, Vec3d d) {
    double t = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (d[a] > 0) t = std::min(t, (size[a] - o[a]) / d[a]);
        if (d[a] < 0) t = std::min(t, -o[a] / d[a]);
    }
    return std::max(t, 0.0);
}

}  // namespace

double sdfSafeStep(const DistanceField& field, Vec3d p, Vec3d d) {
    const double bound = field.conservative(p);
    const Int3 s = field.size();
    const int c[3] = {static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)),
                      static_cast<int>(std::floor(p.z))};
    const bool inside =
        c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < s.x && c[1] < s.y && c[2] < s.z;
    if (inside && field.cell(c[0], c[1], c[2]) <= 0.0f) return 0.0;  // in a solid voxel
    // Leaving the current (empty) cell cannot cross a solid one.
    double cellExit = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (d[a] > 0) cellExit = std::min(cellExit, (c[a] + 1 - p[a]) / d[a]);
        if (d[a] < 0) cellExit = std::min(cellExit, (c[a] - p[a]) / d[a]);
    }
    return std::max(bound, cellExit + kCrossing);
}

SdfShadowResult sdfSunVisibility(const DistanceField& field, Vec3d origin, Vec3d l,
                                 double tanRadius, int maxSteps, bool cubes) {
    SdfShadowResult r;
    const double tMax = exitT(field.size(), origin, l);
    const float w = static_cast<float>(std::max(tanRadius, 1e-6));
    sh::SdfShadowMarch m = sh::sdfShadowBegin(0.0f);
    while (m.steps < maxSteps) {
        if (m.t >= tMax) {
            r.valid = true;  // reached the sky
            break;
        }
        const Vec3d p = origin + l * double(m.t);
        const double h = cubes ? field.surfaceDistance(p) : field.estimate(p);
        sh::sdfShadowStep(m, static_cast<float>(h), static_cast<float>(sdfSafeStep(field, p, l)),
                          w);
        if (m.res <= LUXEL_SDF_RES_DONE) {
            r.valid = true;  // fully shadowed, whatever lies further on
            break;
        }
    }
    if (!r.valid && m.t >= tMax) r.valid = true;
    r.visibility = sh::sdfShadowVisibility(m.res);
    r.steps = m.steps;
    return r;
}

}  // namespace luxel::voxel
