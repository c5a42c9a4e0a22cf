// The picture people look at: emission + fluence, tonemapped (linear [0, 1], ready for writePng).
#pragma once

#include "luxel/core/image.h"
#include "luxel/core/tonemap.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d {

// Emission shows the light sources themselves, fluence the light everywhere else. Both images must
// have the medium's size (checked).
Image displayImage(const Medium2D& medium, const Image& fluence, const ToneMapSettings& tone);

}  // namespace luxel::gi2d
