// The path tracer's surface model, shared with the sky visibility renderer (sky_visibility.h) so
// both see the same albedo, emission, sun shadows and bounce directions
// (docs/algorithms/voxel-path-tracing.md).
#pragma once

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

struct PathBsdf;

struct PathSurface {
    Rgb albedo, emission;
    const Material* material = nullptr;  // the hit voxel's (in shading.materials)
};

// Shadow rays over the sun's disk per face or pixel of the deterministic soft sun (sun_disk.h)
// of the sky visibility renderer.
inline constexpr int kSunDiskRays = 16;

// What the hit face reflects and emits: the physical shading's surface colour (voxel colour x
// texel x procedural texture x material albedo; nearest texel), every material taken as diffuse.
PathSurface pathSurfaceAt(const VoxelWorld& world, const SurfaceHit& s, const ShadeOptions& o);
// The same for the hit voxel's value when the caller has read it.
PathSurface pathSurfaceAt(Voxel voxel, const SurfaceHit& s, const ShadeOptions& o);

// A cosine-weighted unit direction about the axis-aligned normal n from two uniform numbers in
// [0, 1): pdf cos / pi, so a Lambertian bounce weighs albedo exactly.
Vec3d cosineDirection(Int3 normal, float u1, float u2);

// Whether a ray that leaves a surface meets an opaque texel within tMax (cutout texels let it
// through when there are textures; else any solid voxel stops it).
bool surfaceRayBlocked(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                       double tMax, int stepCap);

}  // namespace luxel::voxel
