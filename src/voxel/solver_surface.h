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
// Fresnel at each exit) and takes the solver's light along each ray that leaves it. The sun's
// shadow rays pass through glass with a transmittance (solver_sun.h).
#pragma once

#include <functional>

#include "ggx_albedo.h"
#include "path_trace_bsdf.h"
#include "path_trace_surface.h"

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

class SunRayMap;

// GGX directions sampled per pixel for the specular reflection of the surroundings.
inline constexpr int kSolverSpecularRays = 4;

// Glass and polished metal a reflection or transmission ray may meet and follow, one inside
// another, before the face it meets is shaded as an opaque Lambertian one (each level shades the
// face with its material).
inline constexpr int kSolverFollowDepth = 2;
// Interfaces a transmitted ray may meet inside a medium before what is left is dropped.
inline constexpr int kMaxMediumExits = 8;
// Metals at most this rough are followed: their reflection is sharp.
inline constexpr float kSolverFollowRoughness = 0.1f;
// A GGX lobe at most this sharp (alpha, roughness 0.05: its reflection directions lie within a
// few tenths of a degree, a pixel or two of a 640x360 picture) takes one direction where
// SolverLight::sharpLobeOneRay is set: a second lands where the first did
// (docs/algorithms/voxel-radiance-cascades.md §4.2, "Sharp lobes take one ray").
inline constexpr float kSolverSharpAlpha = 0.0025f;
// A GGX lobe at least this rough (alpha; roughness 0.67, so the default 0.7 is one) takes one
// direction where SolverLight::roughLobeOneRay is set: its specular share is small and spread
// wide, and the picture's 8 x 8 blocks average a second direction's difference away. A rough lobe
// with one direction counts its light unbiased, with the diffuse light E / pi as a control
// variate, rather than by the split sum's weighted mean, which for one direction is that
// direction's radiance alone (docs/algorithms/voxel-radiance-cascades.md §4.2, "Very rough lobes
// take one ray").
inline constexpr float kSolverRoughAlpha = 0.45f;

// Whether a ray that meets a voxel of material `m` follows it with shadeSolverSurface rather than
// taking its face as opaque and Lambertian: glass and water (a transmission lobe, with
// shading.refraction on: what lies behind shows) and polished metal (what it reflects shows).
bool solverFollows(const Material& m, const ShadeOptions& shading);
bool solverFollows(const VoxelWorld& world, const SurfaceHit& s, const ShadeOptions& shading);
// Whether any material of shading.materials is followed.
bool solverFollowsAny(const ShadeOptions& shading);
// Whether the GGX lobe of the voxel a ray met is rough: roughness above kSolverFollowRoughness,
// the metals that are not followed. Its GGX directions follow no glass or polished-metal face
// (docs/algorithms/voxel-radiance-cascades.md §4.2, "Rough lobes follow no face").
bool solverRoughLobe(const VoxelWorld& world, const SurfaceHit& s, const ShadeOptions& shading);

// What a GGX direction of the radiance cascades' camera surface brings (SolverLight::glossyAlong):
// `rest` for the split sum; and a lamp's emission that the surface's light samples could have
// found as well, with their density in that direction (`lightDensity` > 0), which the GGX ray
// counts by the balance heuristic against them, outside the split sum.
struct GlossyAlong {
    Rgb rest, lamp;
    double lightDensity = 0.0;
};

struct SolverLight {
    // Mean cosine-weighted radiance arriving at the face apart from the sun (E / pi).
    Rgb diffuseRadiance;
    // The radiance arriving at the face along a ray leaving it (unit direction). `delta`: the ray
    // left a delta lobe (a mirror, a refraction), so where it escapes to the sky within the sun's
    // disk the disk counts (sunDiskAlong, solver_sun.h); a GGX direction leaves the disk to the
    // sun's highlight. A followed surface passes on `delta` only if its own ray came by delta
    // lobes too: a GGX ray that then passes glass into the disk would count the highlight that
    // the shaded face's sun rays (straight through glass) already counted.
    std::function<Rgb(const Ray&, bool delta)> radianceAlong;
    // Shadow rays over the sun's disk (its fixed spiral; one for a delta sun).
    int sunRays = kSunDiskRays;
    // GGX directions for the specular reflection of the surroundings.
    int specularRays = kSolverSpecularRays;
    // Points whose shadow rays all reach the sky, proven without walking them (null: none).
    const SunRayMap* sunRayMap = nullptr;
    // Set only for the radiance cascades' camera surface (their near term and far lamps, §4.2 of
    // docs/algorithms/voxel-radiance-cascades.md): the light-sampled highlight of the emitters
    // near the surface through its specular-only lobe (glossy, not a mirror); the radiance
    // along its GGX directions in place of radianceAlong(ray, false), which counts those
    // emitters' emission only by the share the highlight leaves and hands back the lamps the
    // light samples could find; and those light samples (`lobeRays`: the GGX directions they
    // are weighed against), drawn after the GGX directions. A lobe at most kSolverSharpAlpha
    // sharp takes no light samples: its GGX direction alone finds a lamp, which it counts in full
    // (§4.2, "Sharp lobes take no lamp samples").
    std::function<Rgb(const PathBsdf& specular)> nearHighlight = nullptr;
    std::function<GlossyAlong(const Ray&)> glossyAlong = nullptr;
    std::function<Rgb(const PathBsdf& specular, int lobeRays, PathRng& rng)> glossyLamps = nullptr;
    // Exits into the air whose refracted light the transmission lobe takes; after the last, the
    // light reflected back inside the medium is dropped (the radiance cascades' picture, whose
    // later exits carry F of it and cost a chain of rays each; kMaxMediumExits: none dropped).
    int mediumAirExits = kMaxMediumExits;
    // The sun's rays take the first one's transmittance where it passed glass or water
    // (solverSunLobes' shareMedia; the radiance cascades' picture).
    bool sunRaysShareMedia = false;
    // A lobe at most kSolverSharpAlpha sharp takes one of the specularRays directions (the
    // radiance cascades' picture).
    bool sharpLobeOneRay = false;
    // A lobe at least kSolverRoughAlpha rough takes one of them too (the radiance cascades'
    // picture).
    bool roughLobeOneRay = false;
};

// The radiance leaving the surface `s` towards the camera ray `ray` (s.hit.normal non-zero).
// `rng` draws the GGX directions (two numbers each).
Rgb shadeSolverSurface(const VoxelWorld& world, const TextureSet* textures, const SurfaceHit& s,
                       const Ray& ray, const ShadeOptions& shading, const SolverLight& light,
                       PathRng& rng);

}  // namespace luxel::voxel
