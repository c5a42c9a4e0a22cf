// Cutout-aware ray casting: castRay, restarted past every cutout texel (see surface_cast.h).
#include "luxel/voxel/surface_cast.h"

#include <new>

#include "voxel/voxel_world_access.h"

namespace luxel::voxel {

Ray continueThroughVoxel(const Ray& ray, const Hit& hit) {
    // The shared kernel (src/gpu/shaders/shared/voxel_dda.h), as the GPU runs it.
    const gpu::shared::dvec3 next =
        gpu::shared::voxelContinueThrough({ray.origin.x, ray.origin.y, ray.origin.z},
                                          {ray.direction.x, ray.direction.y, ray.direction.z},
                                          {hit.voxel.x, hit.voxel.y, hit.voxel.z});
    return {{next.x, next.y, next.z}, ray.direction};
}

SurfaceHit castToSurface(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
                         int stepCap, double tMax, const Hit* cast) {
    // The first cast made straight into the result, the ray read where the caller keeps it:
    // copying the ray in and the hit out read each with wider loads than they had been stored
    // with, and those stalls were a few percent of the radiance cascades' picture
    // (docs/algorithms/voxel-radiance-cascades.md §5). Continuations restart from a copy. The
    // hit is made in place over the default one: an aggregate initialiser with the cast in it
    // cleared the whole result with `rep stos` before the cast filled it in.
    SurfaceHit s;
    if (cast) {
        s.hit = *cast;
    } else {
        new (&s.hit) Hit(castRay(world, ray, tMax, stepCap));
    }
    double tOffset = 0.0;  // t along `ray` of the cast's origin
    for (;;) {
        if (!s.hit.hit) return s;
        s.hit.t += tOffset;
        // No textures: no cutout, and the voxel (often not yet in cache) is left to the shading.
        if (!textures || textures->empty()) {
            s.slot = -1;
            s.texel = Texel{};
            return s;
        }
        const Int3 v = s.hit.voxel;
        const int slot = textureSlotOf(world.get(v.x, v.y, v.z));
        if (slot < 0 || slot >= textures->size()) {
            s.slot = -1;
            s.texel = Texel{};
            return s;
        }
        s.slot = slot;
        s.texel = textures->lookup(slot, s.hit.u, s.hit.v);
        if (!s.texel.cutout()) return s;
        if (s.continuations == kMaxCutoutContinuations) {
            s.cutoutCapped = true;
            s.hit = Hit{};
            s.slot = -1;
            return s;
        }
        ++s.continuations;
        // Exits are computed from the original ray, so the nudges do not add up over many
        // continuations.
        const Ray current = continueThroughVoxel(ray, s.hit);
        const Vec3d& d = ray.direction;
        tOffset = dot(current.origin - ray.origin, d) / dot(d, d);
        s.hit = castRay(world, current, tMax - tOffset, stepCap);
    }
}

}  // namespace luxel::voxel
