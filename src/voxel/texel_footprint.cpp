// Ray-cone footprints on voxel faces: the shared formula (shared/texture_filter.h), which the
// GPU runs too, fed in float.
#include "luxel/voxel/texel_footprint.h"

#include "gpu/shaders/shared/texture_filter.h"

namespace luxel::voxel {

TexelFootprint texelFootprint(const RayCone& cone, double t, Vec3d direction, Int3 normal) {
    const gpu::shared::TexelFootprint f = gpu::shared::textureFootprint(
        static_cast<float>(cone.widthAt(t)),
        {static_cast<float>(direction.x), static_cast<float>(direction.y),
         static_cast<float>(direction.z)},
        {normal.x, normal.y, normal.z});
    return {f.majorU, f.majorV, f.minorU, f.minorV};
}

}  // namespace luxel::voxel
