// A solid face that one of the sun disk's shadow rays stopped at, which proves the disk's other
// rays from the same point blocked without walking them
// (docs/algorithms/voxel-radiance-cascades.md §5, "Shadow rays that share a blocker"). The
// disk's rays leave one point a few degrees apart, so in shadow they mostly stop at the same
// face. A ray that crosses that face's plane towards the solid side, inside the face of a solid
// voxel (farther than kEdgeMargin from its edges), is inside that voxel just past the plane, so
// the exact walk (which visits every cell the ray passes) stops there or earlier: blocked, as
// `occluded` says. This holds while every solid voxel stops a ray: no transmissive media on the
// way (refraction of glass and water off, or none in the scene), no cutout texel anywhere (a
// cutout would let the ray through, and a run of them can end the walk unblocked at
// kMaxCutoutContinuations), and a step cap the walk never reaches (the default cap).
#pragma once

#include <cmath>

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

class SunBlocker {
  public:
    // Crossing points this close to a face's edge (in voxels) prove nothing: the walk's own
    // rounding (about 1e-12 voxels in worlds of thousands) decides which cell it enters there.
    static constexpr double kEdgeMargin = 1e-6;

    // Keeps the face of a blocked ray's hit (the first one given); a hit without a face (a ray
    // that started inside a solid voxel) is not kept.
    void note(const Hit& hit) {
        if (known_ || !hit.hit) return;
        for (int a = 0; a < 3; ++a) {
            if (hit.normal[a] == 0) continue;
            known_ = true;
            axis_ = a;
            towardsSolid_ = -hit.normal[a];
            layer_ = hit.voxel[a];
            // The face's plane: the voxel's side that faces the ray's origin.
            plane_ = double(hit.voxel[a]) + (hit.normal[a] > 0 ? 1.0 : 0.0);
        }
    }

    // True when `ray` provably enters a solid voxel through the kept face's plane; false when
    // nothing is kept or the proof does not apply (the ray must then be walked).
    bool blocks(const VoxelWorld& world, const Ray& ray) const {
        if (!known_) return false;
        const double d = ray.direction[axis_];
        if (!(d * towardsSolid_ > 0.0)) return false;
        const double t = (plane_ - ray.origin[axis_]) / d;
        if (!(t > 0.0) || !std::isfinite(t)) return false;
        Int3 cell;
        cell[axis_] = layer_;
        for (int b = 0; b < 3; ++b) {
            if (b == axis_) continue;
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

  private:
    bool known_ = false;
    int axis_ = 0, towardsSolid_ = 0, layer_ = 0;
    double plane_ = 0.0;
};

}  // namespace luxel::voxel
