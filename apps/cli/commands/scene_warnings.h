// Scene traps that render without an error but not as intended, for `luxel info` and `luxel
// render` to warn about.
#pragma once

#include <string>
#include <vector>

#include "luxel/gi2d/scene2d.h"

namespace luxel::cli {

// Emitters that emit nothing: the background, a shape or image-layer texels with emission in a
// channel whose absorption is 0. A pixel of luxel's medium adds E (1 - exp(-sigma l)) to a ray
// crossing it over a length l (docs/algorithms/pixel-medium.md), so with sigma = 0 its emission
// never reaches anything. One message per emitter, naming it.
std::vector<std::string> silentEmitterWarnings(const gi2d::Scene2D& scene);

// Prints "luxel: warning: <message>" on stderr.
void printWarning(const std::string& message);

}  // namespace luxel::cli
