// Analytic sky models as sky gradients.
#include "luxel/voxel/sky_model.h"

namespace luxel::voxel {

SkyGradient cieOvercastSky(Rgb zenith) {
    // cos θ is the direction's ω_y, the gradient's blend factor: Lz/3 + (Lz − Lz/3) ω_y.
    return {zenith, zenith * (1.0f / 3.0f)};
}

}  // namespace luxel::voxel
