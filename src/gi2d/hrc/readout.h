// HRC read-out, the CPU twin of the hrc_readout pass
// (docs/algorithms/holographic-radiance-cascades.md §6.2).
#pragma once

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/frustum_frame.h"
#include "luxel/core/image.h"

namespace luxel::gi2d::hrc {

// Adds this frustum's angular fluence arriving at every pixel's read-out plane into `beyondSum`
// (canvas space, 3 channels): the merged cones of cascade `level` at the first plane beyond the
// pixel, or the sky times the 90 degrees the cones cover where that plane is outside the frame.
void readOut(const FrustumFrame& frame, const ConeBuffer& cones, int level, Rgb sky,
             Image& beyondSum);

}  // namespace luxel::gi2d::hrc
