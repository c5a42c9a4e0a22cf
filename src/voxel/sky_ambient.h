// The ray caster's sky ambient with occlusion (ShadeOptions::skyAmbientRays;
// docs/algorithms/voxel-surfaces.md, "Sky ambient with occlusion"): from a point on a face,
// cosine-distributed rays find which of the sky the face sees. The GPU twin is
// voxel/sky_ambient.glsl; both draw their directions with shared/sky_ambient.h from the same
// PathRng stream.
#pragma once

#include "luxel/core/vec.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

struct SkyAmbient {
    float visible = 0.0f;  // the share of the rays that reach the sky
    Rgb sky;               // the sky's radiance along them, summed and divided by all the rays
};

// options.skyAmbientRays rays (at least 1) from `point` on the face of normal `normal`, two
// numbers of `rng` each. A ray reaches the sky when it leaves the world without meeting an opaque
// texel: cutout texels let it through, every other solid voxel stops it, glass and emissive ones
// included (as sky visibility's rays, sky_visibility.h). The face's irradiance from the sky is
// π · sky, in expectation ∫ sky(ω) V(ω) cos θ dω.
SkyAmbient traceSkyAmbient(const VoxelWorld& world, const TextureSet* textures, Vec3d point,
                           Int3 normal, const ShadeOptions& options, PathRng& rng);

}  // namespace luxel::voxel
