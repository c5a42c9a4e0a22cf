// HRC one whole cascade at a time (docs/algorithms/holographic-radiance-cascades.md §7): per
// frustum trace and extend every ray table, merge the cones top-down, read out. The passes of the
// GPU solver in the same order, kept on the CPU as their reference, for the debug cascade views,
// and as the check of the streaming solver (sweep_solver.h).
#pragma once

#include "gi2d/hrc/near_lights.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/hrc_solver.h"

namespace luxel::gi2d::hrc {

// The angular fluence arriving at every pixel's read-out plane, summed over the frustums of
// `options.frustumMask` (before finishFluence).
Image levelByLevelBeyond(const Medium2D& medium, const HrcOptions& options);
// The same with the medium's near-light mask (§12.3) made already.
Image levelByLevelBeyond(const Medium2D& medium, const HrcOptions& options,
                         const NearLightMask& nearLights);

// Bytes levelByLevelBeyond holds for a canvas of this size.
std::uint64_t levelByLevelBytes(int width, int height);

}  // namespace luxel::gi2d::hrc
