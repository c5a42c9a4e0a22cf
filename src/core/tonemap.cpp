// Tonemapping curves (clamp, Reinhard, ACES fit) and the sRGB transfer curve.
#include "luxel/core/tonemap.h"

#include <algorithm>
#include <cmath>

namespace luxel {

namespace {

// Narkowicz 2015. Evaluated in double so the curve stays monotonic near its shoulder.
float acesCurve(float x) {
    const double v = x;
    const double y = (v * (2.51 * v + 0.03)) / (v * (2.43 * v + 0.59) + 0.14);
    return static_cast<float>(std::clamp(y, 0.0, 1.0));
}

float applyCurve(float value, float scale, ToneCurve curve) {
    const float x = value * scale;
    // Negative light cannot be displayed; `!(x > 0)` also catches NaN.
    if (!(x > 0.0f)) return 0.0f;
    // Every curve saturates at 1; handling infinity here keeps inf/inf out of Reinhard and ACES.
    if (std::isinf(x)) return 1.0f;
    switch (curve) {
        case ToneCurve::Clamp:
            return std::min(x, 1.0f);
        case ToneCurve::Reinhard:
            return x / (1.0f + x);
        case ToneCurve::Aces:
            return acesCurve(x);
    }
    return 0.0f;
}

}  // namespace

std::optional<ToneCurve> parseToneCurve(std::string_view name) {
    if (name == "clamp") return ToneCurve::Clamp;
    if (name == "reinhard") return ToneCurve::Reinhard;
    if (name == "aces") return ToneCurve::Aces;
    return std::nullopt;
}

Image toneMap(const Image& hdr, const ToneMapSettings& settings) {
    if (hdr.empty()) return Image();
    Image out = hdr;
    const float scale = std::exp2(settings.exposureStops);
    const int channels = hdr.channels();
    // 2 channels are grey + alpha (as readPng returns them), so only the first is colour.
    const int colourChannels = channels == 2 ? 1 : std::min(channels, 3);
    float* p = out.data();
    const std::size_t pixels = out.pixelCount();
    for (std::size_t i = 0; i < pixels; ++i, p += channels) {
        for (int c = 0; c < colourChannels; ++c) p[c] = applyCurve(p[c], scale, settings.curve);
    }
    return out;
}

float linearToSrgb(float linear) {
    // The curve is defined on [0, 1]; clamping (and NaN -> 0) keeps the result there too.
    if (!(linear > 0.0f)) return 0.0f;
    if (linear >= 1.0f) return 1.0f;
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
    if (!(encoded > 0.0f)) return 0.0f;
    if (encoded >= 1.0f) return 1.0f;
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace luxel
