// The material model at the surface a real-time solver's camera ray meets (sky visibility,
// radiance cascades; docs/algorithms/voxel-sky-visibility.md §Materials): the path tracer's lobes
// (path_trace_bsdf.h) with the solver's light in place of paths. With b = pathBsdf(...) and
// E / pi the solver's mean cosine-weighted incoming radiance,
//
//   L = emission + D (E / pi + sun) + S-lobe sun (GGX over the sun's disk, shadow rays)
//       + S A(cos_v, alpha) Lbar(r)
//
// where A is the GGX lobe's directional albedo (directionalAlbedoGgx) and Lbar the radiance
// arriving about the reflection direction: the mean of a few GGX-sampled directions' radiance,
// weighted by their sampling weights (split-sum: exact under light the same from every
// direction). A mirror takes one ray along the reflection. The transmission lobe T follows the
// refracted camera ray through the medium as the path tracer does (walkMedium, Beer-Lambert,
// Fresnel at each exit) and takes the solver's light along each ray that leaves it.
#pragma once

#include <functional>

#include "ggx_albedo.h"
#include "path_trace_surface.h"

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// GGX directions sampled per pixel for the specular reflection of the surroundings.
inline constexpr int kSolverSpecularRays = 4;

struct SolverLight {
    // Mean cosine-weighted radiance arriving at the face apart from the sun (E / pi).
    Rgb diffuseRadiance;
    // The radiance arriving at the face along a ray leaving it (unit direction).
    std::function<Rgb(const Ray&)> radianceAlong;
    // Shadow rays over the sun's disk (its fixed spiral; one for a delta sun).
    int sunRays = kSunDiskRays;
    // GGX directions for the specular reflection of the surroundings.
    int specularRays = kSolverSpecularRays;
};

// The radiance leaving the surface `s` towards the camera ray `ray` (s.hit.normal non-zero).
// `rng` draws the GGX directions (two numbers each).
Rgb shadeSolverSurface(const VoxelWorld& world, const TextureSet* textures, const SurfaceHit& s,
                       const Ray& ray, const ShadeOptions& shading, const SolverLight& light,
                       PathRng& rng);

}  // namespace luxel::voxel
