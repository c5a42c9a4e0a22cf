// Cutout-aware ray casting: castRay, restarted past every cutout texel (see surface_cast.h).
#include "luxel/voxel/surface_cast.h"

#include <algorithm>
#include <cmath>

namespace luxel::voxel {

Ray continueThroughVoxel(const Ray& ray, const Hit& hit) {
    const Vec3d& o = ray.origin;
    const Vec3d& d = ray.direction;
    const Int3 cell = hit.voxel;
    const auto boundary = [&](int a) {
        return static_cast<double>(cell[a] + (d[a] > 0.0 ? 1 : 0));
    };
    // The axis the DDA steps next: the smallest exit t, lowest axis on ties (dda.cpp's order).
    double exitOf[3] = {kInfinity, kInfinity, kInfinity};
    int exitAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) continue;
        exitOf[a] = (boundary(a) - o[a]) / d[a];
        if (exitAxis < 0 || exitOf[a] < exitOf[exitAxis]) exitAxis = a;
    }
    Ray next = ray;
    if (exitAxis < 0) return next;  // zero direction: castRay misses it anyway
    const double tExit = exitOf[exitAxis];
    double previous = 0.0;
    for (int a = 0; a < 3; ++a) {
        const double lo = cell[a], hi = cell[a] + 1.0;
        double p = d[a] == 0.0 ? o[a] : o[a] + tExit * d[a];
        if (a == exitAxis) {
            p = boundary(a);  // on the boundary: castRay starts in the neighbour
        } else if (d[a] != 0.0 && exitOf[a] == tExit) {
            // A tie (the ray leaves through an edge or a corner): the DDA steps this axis right
            // after the exit axis, higher axes later. Start just inside the boundary, far enough
            // that the restarted traversal crosses it after the previous tied axis.
            const double inside = d[a] > 0.0 ? lo : hi;
            // Start where the ray is at t = previous (ulp steps near 0 are too small to walk).
            p = boundary(a) - previous * d[a];
            double t = 0.0;
            do {
                p = std::nextafter(p, inside);
                t = (boundary(a) - p) / d[a];
            } while (!(t > previous));
            previous = t;
        } else if (d[a] > 0.0) {
            p = std::clamp(p, lo, std::nextafter(hi, lo));  // hi would start one cell on
        } else if (d[a] < 0.0) {
            p = std::clamp(p, std::nextafter(lo, hi), hi);  // lo would start one cell lower
        }
        next.origin[a] = p;
    }
    return next;
}

SurfaceHit castToSurface(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                         int stepCap) {
    SurfaceHit s;
    Ray current = ray;
    double tOffset = 0.0;  // t along `ray` of current.origin
    for (;;) {
        s.hit = castRay(world, current, kInfinity, stepCap);
        if (!s.hit.hit) return s;
        s.hit.t += tOffset;
        const Int3 v = s.hit.voxel;
        const int slot = textureSlotOf(world.get(v.x, v.y, v.z));
        if (!textures || slot < 0 || slot >= textures->size()) {
            s.slot = -1;
            s.texel = Texel{};
            return s;
        }
        s.slot = slot;
        s.texel = textures->lookup(slot, s.hit.u, s.hit.v);
        if (!s.texel.cutout()) return s;
        if (s.continuations == kMaxCutoutContinuations) {
            s.cutoutCapped = true;
            s.hit = Hit{};
            s.slot = -1;
            return s;
        }
        ++s.continuations;
        // Exits are computed from the original ray, so the nudges do not add up over many
        // continuations.
        current = continueThroughVoxel(ray, s.hit);
        const Vec3d& d = ray.direction;
        tOffset = dot(current.origin - ray.origin, d) / dot(d, d);
    }
}

}  // namespace luxel::voxel
