// Sky ambient with occlusion on the CPU (sky_ambient.h). The sums run in float in the GPU's order
// (voxel/sky_ambient.glsl), so both backends differ only where a ray grazes an edge.
#include "voxel/sky_ambient.h"

#include <algorithm>

#include "gpu/shaders/shared/sky_ambient.h"
#include "luxel/voxel/dda.h"
#include "path_trace_surface.h"
#include "voxel/shadow_blockers.h"

namespace luxel::voxel {

static_assert(kMaxSkyAmbientRays == LUXEL_SKY_AMBIENT_MAX_RAYS);

SkyAmbient traceSkyAmbient(const VoxelWorld& world, const TextureSet* textures, Vec3d point,
                           Int3 normal, const ShadeOptions& options, PathRng& rng) {
    const int n = std::clamp(options.skyAmbientRays, 1, kMaxSkyAmbientRays);
    int escaped = 0;
    Rgb sky;
    // Under a roof most rays stop at the same few faces, which then answer for the rest.
    const bool share = shadowBlockersHold(textures, options.stepCap);
    ShadowBlockers blockers;
    for (int i = 0; i < n; ++i) {
        const float u1 = rng.next(), u2 = rng.next();
        const gpu::shared::vec3 d =
            gpu::shared::skyAmbientDirection({normal.x, normal.y, normal.z}, u1, u2);
        const Ray ray{point, {d.x, d.y, d.z}};
        const bool blocked =
            share ? blockers.blocked(world, textures, ray, options.stepCap)
                  : surfaceRayBlocked(world, textures, ray, kInfinity, options.stepCap);
        if (blocked) continue;
        ++escaped;
        sky += skyColor(ray.direction, options);
    }
    return {float(escaped) / float(n), sky * (1.0f / float(n))};
}

}  // namespace luxel::voxel
