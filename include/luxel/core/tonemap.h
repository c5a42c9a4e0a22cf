// Tonemapping: HDR linear radiance -> display-referred linear [0, 1], ready for writePng (sRGB).
#pragma once

#include <optional>
#include <string_view>

#include "luxel/core/image.h"

namespace luxel {

enum class ToneCurve {
    Clamp,     // exposure then clamp to [0, 1]
    Reinhard,  // x / (1 + x), per channel
    Aces,      // Narkowicz 2015 fit of the ACES filmic curve
};

std::optional<ToneCurve> parseToneCurve(std::string_view name);  // "clamp" | "reinhard" | "aces"

struct ToneMapSettings {
    float exposureStops = 0.0f;  // multiplies by 2^stops before the curve
    ToneCurve curve = ToneCurve::Aces;
};

// Applies exposure and the curve to the first three channels; alpha (4th) is copied. NaN -> 0.
Image toneMap(const Image& hdr, const ToneMapSettings& settings);

// sRGB transfer curve (IEC 61966-2-1), on one linear value in [0, 1].
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

}  // namespace luxel
