// The sun as the real-time solvers see it (sky visibility, radiance cascades;
// docs/algorithms/voxel-radiance-cascades.md §4.2, docs/algorithms/voxel-sky-visibility.md):
// shadow rays that pass through glass and water with a transmittance, and the sun's disk where a
// mirror or a refracted ray shows it.
//
// The transmittance is taken along the straight line (no refraction): the entry's transmission
// lobe weight, Beer-Lambert over the path inside, the Fresnel transmission where the line leaves.
// On average this conserves the energy that passes; the focusing of refraction (caustics) is
// not drawn.
#pragma once

#include "path_trace_surface.h"
#include "sun_ray_map.h"

#include "luxel/core/vec.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Media (runs of touching transmissive voxels) a sun ray passes before it counts as blocked.
inline constexpr int kMaxSunRayMedia = 8;

// A straight line through transmissive voxels (sunRayTransmittance, and the radiance cascades'
// segments, docs/algorithms/voxel-radiance-cascades.md §4.2): the share that enters the medium
// of `m` through a face with outward normal `normal` along unit `direction` (its transmission
// lobe weight, pathBsdf; 0 for opaque materials), the share that leaves it into the air through
// a face with outward normal `outward` (1 - F at the line's angle), and Beer-Lambert over
// `distance` voxels inside it.
float mediumEntryTransmission(const Material& m, Int3 normal, Vec3d direction,
                              const ShadeOptions& shading);
float mediumExitTransmission(const Material& m, Vec3d direction, Int3 outward,
                             const ShadeOptions& shading);
Rgb mediumAbsorption(const Material& m, double distance);

// What of the light arriving along `ray` from infinity reaches its origin (ray: leaving a
// surface, unit direction): 1 when it meets nothing (cutout texels let it through), 0 at an
// opaque voxel, and through each transmissive voxel it meets (when shading.refraction is on) the
// product of the entry's transmission lobe weight (pathBsdf: (1 - metallic)(1 - F) transmission),
// Beer-Lambert over the straight path inside (the path tracer's absorption) and 1 - F where it
// leaves into the air. A transmissive voxel of another material touching the first is entered
// with its own lobe weight and no exit between them, as the path tracer's rays do. A ray that
// starts on the face of an opaque voxel under glass or water goes out through the medium with
// no entry factor (there is no air between).
Rgb sunRayTransmittance(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                        const ShadeOptions& shading);

// A face a straight line aims at: its voxel and outward normal, or with `extent` (the
// CascadeNearEmitter encoding: size less one along a = (axis + 1) % 3 in the low 16 bits, along
// b = (axis + 2) % 3 in the high 16) the rectangle of faces of that normal from that voxel.
struct FaceTarget {
    Int3 voxel, normal;
    std::uint32_t extent = 0;
};

// What of the light leaving the face `target` along -ray.direction reaches ray.origin, as
// sunRayTransmittance takes it: 1 when the ray meets that face first, a colour when it passes
// glass or water on the way, 0 when it meets another opaque face or leaves the world (the radiance
// cascades' picture near a lamp, docs/algorithms/voxel-radiance-cascades.md §4.1).
Rgb faceRayTransmittance(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                         const ShadeOptions& shading, const FaceTarget& target);

// Whether every solid voxel stops a sun ray: no glass or water lets light through, no texture
// has a cutout texel, the default step cap (shadow rays may then share blockers, ShadowBlockers,
// and a SunRayMap built with solidsStop may prove them blocked).
bool sunRaysStopAtSolids(const TextureSet* textures, const ShadeOptions& shading);

// The sun's light on a face, each shadow ray weighted by its sunRayTransmittance: the diffuse
// lobe `diffuse` and, when given, the GGX lobe of `specular` (whose diffuse lobe must be off;
// each ray a delta light of its share, bsdfLight's highlight computed in float as on the GPU)
// lit by the sun's disk over `sunRays` rays of its spiral (one for a delta sun). No rays when
// neither lobe can reflect. A ray that `map` proves open (its spiral's directions mapped) takes
// transmittance 1 without being walked, and one it proves blocked (while sunRaysStopAtSolids)
// none: the walk's answers. With `shareMedia`, when the spiral's first ray is walked and passes
// glass or water (a transmittance strictly between 0 and 1), the other rays take its
// transmittance without their walks: the disk is a fraction of a degree wide, so they cross the
// same medium (docs/algorithms/voxel-radiance-cascades.md §4.2, "Sun rays through glass"; the
// radiance cascades' camera surface, as on the GPU).
Rgb solverSunLobes(const VoxelWorld& world, const TextureSet* textures, const Hit& hit, Rgb diffuse,
                   const PathBsdf* specular, const ShadeOptions& shading,
                   int sunRays = kSunDiskRays, const SunRayMap* map = nullptr,
                   bool shareMedia = false);

// The radiance of the sun's disk along a unit direction that escapes to the sky after a delta lobe
// (a mirror, a refraction), as the path tracer adds it: 0 outside the disk and for a delta sun.
Rgb sunDiskAlong(Vec3d direction, const ShadeOptions& shading);

}  // namespace luxel::voxel
