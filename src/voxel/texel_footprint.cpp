// Ray-cone footprints on voxel faces.
#include "luxel/voxel/texel_footprint.h"

namespace luxel::voxel {

TexelFootprint texelFootprint(const RayCone&, double, Vec3d, Int3) {
    return {};
}

}  // namespace luxel::voxel
