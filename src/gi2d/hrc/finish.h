// The end of HRC, the CPU twin of the hrc_finish pass
// (docs/algorithms/holographic-radiance-cascades.md §6.2, §7).
#pragma once

#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

// Mean radiance over directions from the light `beyond` arriving at the read-out planes (summed
// over `frustums` frustums): the opacity-gated cross blur of paper Eq 21 when `blur` (applied
// before the pixel's own segment: blurring own emission would smear an emitter into the opaque
// wall next to it), then each pixel's own half-pixel segment in front, then / 2 pi.
Image finishFluence(const Medium2D& medium, const Image& beyond, int frustums, bool blur);

// The same, overwriting `fluence` (the light beyond) with the result: no second image.
void finishFluenceInPlace(const Medium2D& medium, Image& fluence, int frustums, bool blur);

}  // namespace luxel::gi2d::hrc
