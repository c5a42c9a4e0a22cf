// Solid faces that earlier shadow rays from one point stopped at, which prove later rays from
// that point blocked without walking them (docs/algorithms/voxel-radiance-cascades.md §5, "Shadow
// rays that share a blocker"): the sun disk's rays leave a point a few degrees apart, and in
// shadow they mostly stop at the same face; a point's sky ambient rays in a room mostly stop at
// its ceiling and walls. A ray that crosses a kept face's plane towards the solid side, inside
// the face of a solid voxel (farther than kEdgeMargin from its edges), is inside that voxel just
// past the plane, so the exact walk (which visits every cell the ray passes) stops there or
// earlier: blocked, as `occluded` says. This holds while every solid voxel stops a ray
// (shadowBlockersHold), and, for the sun, while no glass or water lets it through. The glossy
// lamps' rays ask for a stop short of the lamp (`before`), from faces kept over many pixels
// (§5, "The glossy lamps' rays").
#pragma once

#include <cmath>

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Whether every solid voxel stops a ray for surfaceRayBlocked: no cutout texel anywhere (a
// cutout lets the ray through, and a run of them can end the walk unblocked at
// kMaxCutoutContinuations) and the default step cap (stepCap 0, which no walk reaches).
inline bool shadowBlockersHold(const TextureSet* textures, int stepCap) {
    return !(textures && !textures->empty() && textures->anyCutout()) && stepCap == 0;
}

class ShadowBlockers {
  public:
    // Crossing points this close to a face's edge (in voxels) prove nothing: the walk's own
    // rounding (about 1e-12 voxels in worlds of thousands) decides which cell it enters there.
    static constexpr double kEdgeMargin = 1e-6;
    // Faces kept: a room's ceiling, its four walls and one more.
    static constexpr int kFaces = 6;

    // Keeps the face of a blocked ray's hit while there is room and its plane is not kept yet; a
    // hit without a face (a ray that started inside a solid voxel) is not kept. With `replace`,
    // a new plane takes the oldest one's place when all are taken (a cache over many points).
    void note(const Hit& hit, bool replace = false) {
        if ((count_ == kFaces && !replace) || !hit.hit) return;
        for (int a = 0; a < 3; ++a) {
            if (hit.normal[a] == 0) continue;
            // The face's plane: the voxel's side that faces the ray's origin.
            const Plane p{a, -hit.normal[a], hit.voxel[a],
                          double(hit.voxel[a]) + (hit.normal[a] > 0 ? 1.0 : 0.0)};
            for (int k = 0; k < count_; ++k) {
                if (planes_[k].axis == p.axis && planes_[k].layer == p.layer &&
                    planes_[k].towardsSolid == p.towardsSolid) {
                    return;
                }
            }
            if (count_ < kFaces) {
                planes_[count_++] = p;
            } else {
                planes_[oldest_] = p;
                oldest_ = (oldest_ + 1) % kFaces;
            }
        }
    }

    // True when `ray` provably enters a solid voxel through a kept face's plane, where it has
    // gone less than `before` (in units of its direction's length); false when no kept face
    // proves it (the ray must then be walked).
    bool blocks(const VoxelWorld& world, const Ray& ray, double before = kInfinity) const {
        for (int k = 0; k < count_; ++k) {
            if (blocksThrough(planes_[k], world, ray, before)) return true;
        }
        return false;
    }

    // surfaceRayBlocked(world, textures, ray, kInfinity, stepCap) where shadowBlockersHold: a
    // kept face's proof, else the walk, whose stopping face is kept.
    bool blocked(const VoxelWorld& world, const TextureSet* textures, const Ray& ray, int stepCap) {
        if (blocks(world, ray)) return true;
        const Hit stop = textures && !textures->empty()
                             ? castToSurface(world, textures, ray, stepCap).hit
                             : castRay(world, ray, kInfinity, stepCap);
        note(stop);
        return stop.hit;
    }

  private:
    struct Plane {
        int axis, towardsSolid, layer;
        double at;
    };

    static bool blocksThrough(const Plane& plane, const VoxelWorld& world, const Ray& ray,
                              double before) {
        const double d = ray.direction[plane.axis];
        if (!(d * plane.towardsSolid > 0.0)) return false;
        const double t = (plane.at - ray.origin[plane.axis]) / d;
        if (!(t > 0.0) || !std::isfinite(t) || !(t < before)) return false;
        Int3 cell;
        cell[plane.axis] = plane.layer;
        for (int b = 0; b < 3; ++b) {
            if (b == plane.axis) continue;
            const double p = ray.origin[b] + t * ray.direction[b];
            const double f = std::floor(p);
            if (!(p - f > kEdgeMargin && f + 1.0 - p > kEdgeMargin)) return false;
            cell[b] = int(f);
        }
        const Int3 size = world.size();
        for (int b = 0; b < 3; ++b) {
            if (cell[b] < 0 || cell[b] >= size[b]) return false;
        }
        return world.solid(cell.x, cell.y, cell.z);
    }

    int count_ = 0, oldest_ = 0;
    Plane planes_[kFaces];
};

}  // namespace luxel::voxel
