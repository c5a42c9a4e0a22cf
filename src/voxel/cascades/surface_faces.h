// The voxel faces light can leave from: every face of a solid voxel whose neighbour across it is
// empty or textured with cutout texels (so a ray can reach the face), and every face of an opaque
// voxel under glass or water (light reaches it through the medium). They are the surface
// probes of the voxel radiance cascades and the radiance cache that probe rays read
// (docs/algorithms/voxel-radiance-cascades.md §3).
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel::cascades {

struct Face {
    Int3 voxel;
    std::uint8_t normal = 0;  // normalIndex of the outward normal
};

class FaceTable {
  public:
    // Scans the world; fails (naming the count and bytes) past `maxFaces`. With `shading`, the
    // faces of opaque voxels towards transmissive ones (shading.refraction on) are open too.
    static Result<FaceTable> build(const VoxelWorld& world, const TextureSet* textures,
                                   std::int64_t maxFaces, const ShadeOptions* shading = nullptr);
    // Faces an upper bound of which build() would find, without building (a fast estimate for
    // memory checks): the solid voxels' faces towards non-solid neighbours.
    static std::int64_t countExposed(const VoxelWorld& world);

    int size() const { return int(faces_.size()); }
    const Face& operator[](int id) const { return faces_[id]; }
    const std::vector<Face>& faces() const { return faces_; }
    // The face's id, or -1 when (voxel, normal) is not in the table.
    int find(Int3 voxel, int normal) const;
    // find() of face `id`'s neighbour in its plane, da and db (-1..1, not both 0) voxels along
    // its plane's axes a = (axis + 1) % 3 and b = (axis + 2) % 3, with the same normal: found once
    // when built, as the picture's interpolation reads them at every hit (§5).
    int neighbour(int id, int da, int db) const {
        const int k = (db + 1) * 3 + (da + 1);
        return neighbours_[std::size_t(id) * 8 + std::size_t(k - (k > 4))];
    }
    std::uint64_t bytes() const;

  private:
    std::uint64_t key(Int3 v, int normal) const {
        return ((std::uint64_t(v.z) * size_.y + std::uint64_t(v.y)) * size_.x +
                std::uint64_t(v.x)) *
                   6 +
               std::uint64_t(normal);
    }
    // Open addressing: a slot's key and id side by side, so that a lookup (the picture makes
    // about a dozen per pixel, each a cache miss in a large table) reads one place, not two; 12
    // bytes, as separate key and id arrays took.
    struct Slot {
        std::uint32_t keyLow = 0, keyHigh = 0;  // key + 1; 0 = empty
        std::int32_t id = -1;
        std::uint64_t stored() const { return std::uint64_t(keyHigh) << 32 | keyLow; }
    };
    static_assert(sizeof(Slot) == 12);
    Int3 size_;
    std::vector<Face> faces_;
    std::vector<Slot> slots_;
    std::vector<std::int32_t> neighbours_;  // 8 per face, by neighbour()'s order
    std::uint64_t mask_ = 0;
};

// The centre of a face.
Vec3d faceCentre(const Face& face);
// The centre of quarter `i` (0..3) of a face: where the sun and the emitters are sampled.
Vec3d faceQuarterCentre(const Face& face, int i);

}  // namespace luxel::voxel::cascades
