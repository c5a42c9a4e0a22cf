// The signed Euclidean distance field of a voxel world for SDF soft shadows: the exact
// Felzenszwalb & Huttenlocher (2012) distance transform, separable in x, y and z, of the solid
// voxels (for empty cells) and of the empty ones (for solid cells). Distances are in voxels.
//
// Each cell stores s = d - 1/2 for an empty cell (d: distance from its centre to the nearest solid
// voxel's centre) and -(d - 1/2) for a solid one (d: to the nearest empty centre), clamped to
// [-kCap, kCap]. The 1/2 makes s exact for flat faces and zero on them, so the trilinear field
// (estimate) crosses zero at the surface. Outside the world everything is empty.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Squared distance of every cell of a size.x * size.y * size.z box (x fastest) to the nearest cell
// whose `feature` is non-zero, in cells; kEdtInfinity where there is none. Exact: the results are
// integers (Felzenszwalb & Huttenlocher 2012, lower envelope of parabolas per axis).
inline constexpr double kEdtInfinity = 1e20;
// With `nearest`, also the feature transform: the index of each cell's nearest feature cell (one
// of them on ties; -1 where there is none).
std::vector<double> squaredDistanceTransform(Int3 size, const std::vector<std::uint8_t>& feature,
                                             std::vector<std::int32_t>* nearest = nullptr);

class DistanceField {
  public:
    // |s| is clamped here, so an edit changes cells only within this distance (region updates).
    static constexpr float kCap = 16.0f;
    // Every point of a cube lies within sqrt(3)/2 of its centre.
    static constexpr double kHalfDiagonal = 0.8660254037844386;

    static DistanceField build(const VoxelWorld& world);

    // Recomputes the cells an edit of the voxels in [min, maxExclusive) can change (the box padded
    // by kCap, from the voxels in the box padded by 2 kCap): equal to a full rebuild.
    void update(const VoxelWorld& world, Int3 min, Int3 maxExclusive);

    Int3 size() const { return size_; }
    // The stored value of a cell (indices clamped into the world).
    float cell(int x, int y, int z) const;
    const std::vector<float>& values() const { return values_; }
    // Per cell, the offset to its nearest voxel of the other kind (the feature transform of the
    // same pass), packed by packSdfFeature (shared/soft_shadow.h).
    const std::vector<std::uint32_t>& features() const { return features_; }

    // A lower bound on the distance from p to the nearest solid voxel (<= 0 where unsure or
    // inside): the distance from the centre c of p's cell to the nearest solid centre, minus
    // |p - c|, minus kHalfDiagonal. A sphere tracer stepping by it never enters a solid voxel.
    double conservative(Vec3d p) const;
    // The trilinear interpolation of the stored values at p: the signed distance to the surface,
    // exact next to flat faces (used for the penumbra estimate, not for stepping).
    double estimate(Vec3d p) const;
    // The signed distance from p to the surface of the voxel cubes (negative inside): the nearest
    // of the cubes that the 8 cells around p name (the cells themselves and their nearest
    // features). Exact next to edges and corners where the centre field is not; it can exceed the
    // true distance only where the nearest cube is none of those (rare, tested), so it drives the
    // penumbra estimate while conservative() drives the steps.
    double surfaceDistance(Vec3d p) const;

  private:
    void compute(const VoxelWorld& world, Int3 inLo, Int3 inHi, Int3 outLo, Int3 outHi);
    // Outside the world: empty, kCap, no feature.
    float cornerValue(int x, int y, int z) const;
    std::uint32_t cornerFeature(int x, int y, int z) const;
    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * size_.y + y) * size_.x + x;
    }

    Int3 size_;
    std::vector<float> values_;
    std::vector<std::uint32_t> features_;
};

}  // namespace luxel::voxel
