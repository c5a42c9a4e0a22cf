// Physical lighting of the voxel renderer (ShadeOptions::Lighting::Physical): materials, sun
// visibility, GGX or Blinn-Phong highlights, Fresnel-weighted mirror reflections and refraction
// through transmissive voxels. Design: docs/algorithms/voxel-surfaces.md.
#pragma once

#include <cmath>

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/ray_cone.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Where a ray inside a transmissive medium leaves it: the medium is the 6-connected voxels with
// the same alpha byte (material) as `cell`, walked with an exact DDA from `origin` (inside or on
// the boundary of `cell`) along the unit `direction`.
struct MediumExit {
    double distance = 0;     // path length inside the medium
    Vec3d point;             // on the exit face
    Int3 cell;               // the last medium voxel
    Int3 outward;            // exit face normal, pointing out of the medium
    bool intoSolid = false;  // the next voxel is solid (another material); else empty or outside
};
MediumExit walkMedium(const VoxelWorld& world, Int3 cell, Vec3d origin, Vec3d direction);

// What happens where a ray inside a medium of index `ior` meets its face with outward normal
// `outward` (air outside): total internal reflection (k < 0, reflectance 1), or a Fresnel split
// into the refracted ray leaving and the ray reflected back inside.
struct ExitSplit {
    bool total = false;
    float reflectance = 1.0f;
    Vec3d reflected, refracted;  // unit; refracted only when !total
};
ExitSplit splitAtExit(Vec3d direction, Int3 outward, float ior, ShadeOptions::FresnelModel fresnel);

// The unit direction the physical model casts a ray along; false for a zero, infinite or NaN
// direction, which it shades as the sky without a cast.
inline bool physicalRayDirection(Vec3d direction, Vec3d& unit) {
    const double len = length(direction);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    unit = direction / len;
    return true;
}

// `sample` keys the random numbers of the sky ambient rays (ShadeOptions::skyAmbientRays).
Rgb shadePhysical(const VoxelWorld& world, const Ray& ray, const RayCone& cone,
                  const ShadeOptions& options, const TextureSet* textures, RaySample sample);

}  // namespace luxel::voxel
