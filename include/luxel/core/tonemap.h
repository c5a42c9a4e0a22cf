// Tonemapping: HDR linear radiance -> display-referred linear [0, 1], ready for writePng (sRGB).
#pragma once

#include <optional>
#include <string_view>

#include "luxel/core/image.h"
#include "luxel/core/image_rows.h"

namespace luxel {

enum class ToneCurve {
    Clamp,     // exposure then clamp to [0, 1]
    Reinhard,  // x / (1 + x), per channel
    Aces,      // Narkowicz 2015 fit of the ACES filmic curve
};

std::optional<ToneCurve> parseToneCurve(std::string_view name);  // "clamp" | "reinhard" | "aces"
const char* toneCurveName(ToneCurve curve);                      // the name parseToneCurve reads

struct ToneMapSettings {
    float exposureStops = 0.0f;  // multiplies by 2^stops before the curve
    ToneCurve curve = ToneCurve::Aces;
};

// Applies exposure and the curve to the first three channels; alpha (4th) is copied. NaN -> 0.
Image toneMap(const Image& hdr, const ToneMapSettings& settings);
// The same in place on `pixels` pixels of `channels` channels (a strip of rows): toneMap without
// the copy.
void toneMapPixels(float* data, std::size_t pixels, int channels, const ToneMapSettings& settings);

// Auto exposure (`--exposure auto`): the stops that map the 99th percentile of the brightest
// channel, over the pixels with any light (max channel > 0; NaN and infinity are skipped), to 90%
// of display white under `curve`. A bright light covering less than 1% of the lit pixels may
// clip; everything else keeps its colour. 0 for an image with no light; clamped to +-64 stops.
inline constexpr double kAutoExposurePercentile = 0.99;
inline constexpr float kAutoExposureWhite = 0.9f;
float autoExposureStops(const Image& hdr, ToneCurve curve);
// The same read strip by strip (the brightest channel of each lit pixel is kept, 4 bytes a pixel).
float autoExposureStops(const ImageRows& hdr, ToneCurve curve);

// The fraction of pixels of a tonemapped image (display-referred linear, as toneMap returns)
// with a colour channel at display white: 255 once encoded as 8-bit sRGB. Pixels where `ignore`
// (same size, or null) has a channel above 0, such as the light sources themselves, count
// neither way.
double clippedFraction(const Image& display, const Image* ignore = nullptr);
// The same counted strip by strip: add() each strip of the tonemapped image (and of `ignore`, or
// null), then fraction().
struct ClippedPixels {
    std::size_t clipped = 0, counted = 0;
    void add(const float* display, int channels, const float* ignore, int ignoreChannels,
             std::size_t pixels);
    double fraction() const;
};
// The smallest display-referred linear value that 8-bit sRGB encodes as 255.
float displayWhiteLevel();

// sRGB transfer curve (IEC 61966-2-1), on one linear value in [0, 1].
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

}  // namespace luxel
