// Emissive voxels as lights for the path tracer's next event estimation
// (docs/algorithms/voxel-path-tracing.md): the list of voxels whose material emits, and the
// sampling of a point on one of their faces, with its probability density in solid angle, so
// that light samples and bounce rays can be combined by multiple importance sampling.
#pragma once

#include <span>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/material.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Most emitters listed (12 bytes each); a world with more leaves its emitters to bounce rays.
inline constexpr int kMaxPathEmitters = 1 << 24;

class PathEmitters {
  public:
    // Every solid voxel whose material (materials.forSlot of its texture slot) emits; an empty
    // list, without a scan, when no material emits, and when more than kMaxPathEmitters do.
    static PathEmitters find(const VoxelWorld& world, const MaterialTable& materials);

    bool empty() const { return voxels_.empty(); }
    int size() const { return static_cast<int>(voxels_.size()); }
    // The emitters in the order sample() picks them (the GPU tracer uploads them).
    std::span<const Int3> voxels() const { return voxels_; }

    struct Sample {
        Int3 voxel;
        Int3 normal;      // the face's outward normal
        Vec3d direction;  // unit, from the shading point to the sampled point
        double distance = 0;
        double pdf = 0;  // solid angle density; 0: no face of the voxel faces the point
    };
    // A voxel chosen uniformly, one of its faces that face `point` (whose planes it lies in front
    // of) uniformly, and a uniform point on that face.
    Sample sample(Vec3d point, float u0, float u1, float u2, float u3) const;

    // The density sample() gives, from `point`, to the point `hit` on face `normal` of `voxel`.
    double pdf(Vec3d point, Int3 voxel, Int3 normal, Vec3d hit) const;

  private:
    std::vector<Int3> voxels_;
};

}  // namespace luxel::voxel
