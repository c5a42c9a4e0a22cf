// Tonemapping curves (clamp, Reinhard, ACES fit) and the sRGB transfer curve.
#include "luxel/core/tonemap.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

const char* toneCurveName(ToneCurve curve) {
    switch (curve) {
        case ToneCurve::Clamp:
            return "clamp";
        case ToneCurve::Reinhard:
            return "reinhard";
        case ToneCurve::Aces:
            break;
    }
    return "aces";
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

float autoExposureStops(const Image& hdr, ToneCurve curve) {
    if (hdr.empty()) return 0.0f;
    const int channels = hdr.channels();
    const int colourChannels = channels == 2 ? 1 : std::min(channels, 3);
    std::vector<float> brightest;
    brightest.reserve(hdr.pixelCount());
    const float* p = hdr.data();
    for (std::size_t i = 0; i < hdr.pixelCount(); ++i, p += channels) {
        float v = 0.0f;
        for (int c = 0; c < colourChannels; ++c) {
            if (std::isfinite(p[c])) v = std::max(v, p[c]);
        }
        if (v > 0.0f) brightest.push_back(v);
    }
    if (brightest.empty()) return 0.0f;
    const auto at = brightest.begin() +
                    static_cast<std::ptrdiff_t>(kAutoExposurePercentile * (brightest.size() - 1));
    std::nth_element(brightest.begin(), at, brightest.end());
    // The curve's input that displays as kAutoExposureWhite, by bisection (every curve is
    // monotonic and reaches 0.9 below 1e3).
    double lo = 0.0, hi = 1e3;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (applyCurve(static_cast<float>(mid), 1.0f, curve) < kAutoExposureWhite ? lo : hi) = mid;
    }
    const double stops = std::log2(0.5 * (lo + hi) / static_cast<double>(*at));
    return static_cast<float>(std::clamp(stops, -64.0, 64.0));
}

double clippedFraction(const Image& display, const Image* ignore) {
    if (display.empty()) return 0.0;
    LUXEL_CHECK(ignore == nullptr ||
                (ignore->width() == display.width() && ignore->height() == display.height()));
    const float white = displayWhiteLevel();
    const int channels = display.channels();
    const int colourChannels = channels == 2 ? 1 : std::min(channels, 3);
    std::size_t clipped = 0, counted = 0;
    for (int y = 0; y < display.height(); ++y) {
        for (int x = 0; x < display.width(); ++x) {
            if (ignore != nullptr) {
                const Rgb v = ignore->rgb(x, y);
                if (v.r > 0.0f || v.g > 0.0f || v.b > 0.0f) continue;
            }
            ++counted;
            for (int c = 0; c < colourChannels; ++c) {
                if (display.at(x, y, c) >= white) {
                    ++clipped;
                    break;
                }
            }
        }
    }
    return counted > 0 ? static_cast<double>(clipped) / static_cast<double>(counted) : 0.0;
}

float displayWhiteLevel() {
    // linearToSrgb(v) * 255 rounds to 255 from here on.
    static const float white = srgbToLinear(254.5f / 255.0f);
    return white;
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
