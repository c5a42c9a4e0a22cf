// The ray caster's light from emissive voxels (physical lighting;
// docs/algorithms/voxel-surfaces.md, "Light from emissive voxels"): every open face of an emissive
// voxel lights the points in front of it by its exact unoccluded irradiance (Lambert's contour
// integral) times the mean transmittance of a fixed set of shadow rays to the face. A grid lists
// for each cube of the world the faces that can light it by more than a floor, so the cost per
// point does not grow with the size of the world. The GPU runs the same from the same lists
// (emitter_light.glsl).
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/material.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

struct ShadeOptions;

// Shadow rays per face (render.emitter_rays): 1..kMaxEmitterRays (LUXEL_EMITTER_MAX_RAYS).
inline constexpr int kMaxEmitterRays = 64;
// Shadow rays over all the hits of one camera sample's path (LUXEL_EMITTER_PATH_RAYS).
inline constexpr int kEmitterPathRays = 64;
// The default floor (LUXEL_EMITTER_FLOOR, src/gpu/shaders/shared/emitter_light.h).
inline constexpr float kEmitterFloor = 5e-4f;

// An emitter as the GPU reads it (CascadeNearEmitter, shared/near_emitters.h): a rectangle of
// open faces of one radiance on one plane, from its voxel, with its normal index (0 +x, 1 -x,
// 2 +y, 3 -y, 4 +z, 5 -z), radiance and extent (size less one along a = (axis + 1) % 3 in the
// low 16 bits, along b = (axis + 2) % 3 in the high 16; 0: one face).
struct EmitterFace {
    int x = 0, y = 0, z = 0;
    std::uint32_t normal = 0;
    float r = 0, g = 0, b = 0;
    std::uint32_t extent = 0;
};

// Most open emissive faces lit by; a world with more has no light from them in the ray caster.
inline constexpr int kMaxEmitterFaces = 1 << 20;
// Most entries in the grid's lists (4 bytes each): past it the floor is raised until they fit.
inline constexpr std::int64_t kMaxEmitterListEntries = std::int64_t(1) << 24;

class EmitterLights {
  public:
    // The open faces (the neighbour along the normal is inside the world and empty) of every
    // voxel whose material emits, merged into rectangles of up to LUXEL_EMITTER_RECT_SIDE faces
    // a side (coplanar, of one radiance), and the grid's lists. Empty when nothing emits or the
    // world holds more than kMaxEmitterFaces such faces.
    static EmitterLights build(const VoxelWorld& world, const MaterialTable& materials);

    bool empty() const { return faces_.empty(); }
    // The open emissive faces, and the rectangles they were merged into.
    int faceCount() const { return openFaces_; }
    int emitterCount() const { return static_cast<int>(faces_.size()); }
    // The irradiance (largest channel) below which a face lights a point not at all: the
    // default kEmitterFloor, doubled as often as the lists needed to fit their bound.
    float floor() const { return floor_; }
    Int3 cells() const { return cells_; }

    // The GPU's buffers 15..17 (shared/emitter_light.h).
    const std::vector<std::uint32_t>& cellOffsets() const { return cellOffsets_; }
    const std::vector<std::uint32_t>& cellFaces() const { return cellFaces_; }
    const std::vector<EmitterFace>& faces() const { return faces_; }

    // What a surface reflects to `view` of the emitters' light at `point` on a face with normal
    // `faceNormal`: diffuseAlbedo/pi times the irradiance, plus `specularWeight` times the
    // specular lobe (ShadeOptions::specular, f0, alpha about `shadingNormal`) summed over the
    // shadow rays, each the delta light of its share of the emitter. `rays`: shadow rays per
    // emitter.
    struct Surface {
        Vec3d point;
        Int3 faceNormal;
        Vec3 shadingNormal, view;  // unit
        Rgb diffuseAlbedo;
        Vec3 f0;
        float alpha = 1.0f;
        int specularModel = 0;  // LUXEL_VOXEL_SPECULAR_*
        float specularWeight = 0.0f;
    };
    // `budget`: shadow rays the camera sample's path may still cast (kEmitterPathRays at its
    // start); this hit takes as many of its strongest emitters as it allows and spends their
    // rays.
    Rgb light(const VoxelWorld& world, const TextureSet* textures, const Surface& surface,
              const ShadeOptions& shading, int rays, int& budget) const;

  private:
    std::vector<EmitterFace> faces_;
    int openFaces_ = 0;
    std::vector<std::uint32_t> cellOffsets_, cellFaces_;
    Int3 cells_;
    float floor_ = kEmitterFloor;
};

}  // namespace luxel::voxel
