// Sun rays proven open or blocked without being walked
// (docs/algorithms/voxel-radiance-cascades.md §5, "Sunlit rays proven open"): a sunlit pixel's
// shadow rays all leave the world, a shadowed one's all stop, and walking each of them was a
// large part of a frame.
//
// The real-time solvers cast their sun rays along a fixed spiral over the disk (sun_disk.h), so
// the directions are known in advance. For each, a map of the world seen from that direction:
// every solid voxel with a non-solid neighbour marks the texels its projection along the
// direction touches with its coordinate along each face normal the direction leaves. A ray from
// a point p on such a face projects onto p's own texel all along its length and never goes back
// below p's face plane, and the first solid cell the exact walk enters is one with a non-solid
// neighbour. So when no voxel on the outer side of p's face plane marks p's texel, and the cells
// the walk may start in are empty, the walk meets nothing: the ray's transmittance is exactly 1,
// as sunRayTransmittance finds it. Where every solid stops a ray, a texel wholly inside a
// voxel's projection keeps how far along the direction that voxel begins: a ray from behind it
// passes through its inside, and the walk stops there or earlier. Anything else proves nothing
// and the ray is walked.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// What a SunRayMap proves of one ray.
enum class SunRayProof { None, Open, Blocked };

class SunRayMap {
  public:
    // Texels per map side at most; larger worlds get coarser texels (fewer proofs, same answers).
    static constexpr int kMaxTexelsPerSide = 512;
    // Directions mapped at most (their maps' bytes grow with each).
    static constexpr int kMaxDirections = 32;
    // Worlds the renderers that make a map per picture (sky visibility) map at most: the scan
    // of a larger one costs more than its picture's walks save.
    static constexpr std::int64_t kMaxWorldVoxels = std::int64_t(1) << 24;

    // Nothing proven (every query false).
    SunRayMap() = default;
    // One map per unit direction of `directions` (repeats mapped once; past kMaxDirections the
    // rest are not mapped) of `world` as it is now. With `solidsStop` (every solid voxel stops
    // a ray: sunRaysStopAtSolids, solver_sun.h) the maps also prove rays blocked.
    static SunRayMap build(const VoxelWorld& world, std::span<const Vec3d> directions,
                           bool solidsStop = false);

    // Whether the cells a ray from hit.point (on the face of hit.voxel with outward hit.normal,
    // as castRay reports it) may start its walk in are empty: open() needs it for every ray.
    bool startsClear(const VoxelWorld& world, const Hit& hit) const;
    // Given startsClear, whether the ray from hit.point along `direction` (one of the mapped
    // directions, bit for bit; any other proves nothing) leaves the world without entering a
    // solid voxel. False proves nothing.
    bool rayOpen(const Hit& hit, const Vec3d& direction) const;
    bool open(const VoxelWorld& world, const Hit& hit, const Vec3d& direction) const {
        return startsClear(world, hit) && rayOpen(hit, direction);
    }
    // Whether the ray from hit.point along `direction` (a mapped direction) passes through the
    // inside of a solid voxel ahead of it, so that the exact walk stops there or earlier: with
    // the map built with solidsStop, and while every solid still stops a ray. False proves
    // nothing.
    bool rayBlocked(const Hit& hit, const Vec3d& direction) const;
    // rayOpen (when `startsClear`) and rayBlocked at once, the texel found once: Open, Blocked
    // or None.
    SunRayProof prove(const Hit& hit, const Vec3d& direction, bool startsClear) const;
    // prove(hit, direction, startsClear(world, hit)), with startsClear asked only where a proof
    // of an open ray needs it: `clear` is -1 until it is found, then its answer, kept for the
    // hit's next rays. The same answers; a ray whose texel a voxel beyond the face marks (every
    // ray of a closed room) reads no cell around its start.
    SunRayProof prove(const VoxelWorld& world, const Hit& hit, const Vec3d& direction,
                      int& clear) const;
    int directions() const { return int(views_.size()); }
    std::uint64_t bytes() const;

  private:
    // The world seen along one direction: per face normal it leaves (`on`), per texel the
    // largest coordinate along that normal (times its sign) of the voxels that mark it.
    struct View {
        Vec3d direction, tangentU, tangentV;
        double originU = 0.0, originV = 0.0, texel = 1.0, perTexel = 1.0;  // 1 / texel
        int sizeU = 0, sizeV = 0;
        std::array<bool, 6> on{};
        std::array<std::vector<std::int16_t>, 6> key;
        // With solidsStop, per texel: the largest least depth along the direction of the voxels
        // whose projection holds the texel inside it (a ray through the texel passes through
        // their inside), -inf where none.
        std::vector<float> ahead;
    };
    static View mapOne(Int3 size, Vec3d direction, const std::vector<Int3>& exposedVoxels,
                       bool solidsStop);
    const View* viewOf(const Vec3d& direction) const;
    std::vector<View> views_;
};

}  // namespace luxel::voxel
