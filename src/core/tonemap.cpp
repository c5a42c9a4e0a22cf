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
    toneMapPixels(out.data(), out.pixelCount(), out.channels(), settings);
    return out;
}

void toneMapPixels(float* data, std::size_t pixels, int channels, const ToneMapSettings& settings) {
    const float scale = std::exp2(settings.exposureStops);
    // 2 channels are grey + alpha (as readPng returns them), so only the first is colour.
    const int colourChannels = channels == 2 ? 1 : std::min(channels, 3);
    float* p = data;
    for (std::size_t i = 0; i < pixels; ++i, p += channels) {
        for (int c = 0; c < colourChannels; ++c) p[c] = applyCurve(p[c], scale, settings.curve);
    }
}

float autoExposureStops(const Image& hdr, ToneCurve curve) {
    return autoExposureStops(rowsOf(hdr), curve);
}

float autoExposureStops(const ImageRows& hdr, ToneCurve curve) {
    if (hdr.empty()) return 0.0f;
    const int channels = hdr.channels;
    const int colourChannels = channels == 2 ? 1 : std::min(channels, 3);
    std::vector<float> brightest;
    // Pages of the reserve that no lit pixel reaches are never touched.
    brightest.reserve(static_cast<std::size_t>(hdr.width) * hdr.height);
    forEachStrip(hdr, kImageStripRows, [&](int y0, int y1, const float* p) {
        const std::size_t pixels = static_cast<std::size_t>(y1 - y0) * hdr.width;
        for (std::size_t i = 0; i < pixels; ++i, p += channels) {
            float v = 0.0f;
            for (int c = 0; c < colourChannels; ++c) {
                if (std::isfinite(p[c])) v = std::max(v, p[c]);
            }
            if (v > 0.0f) brightest.push_back(v);
        }
    });
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
    ClippedPixels count;
    count.add(display.data(), display.channels(), ignore != nullptr ? ignore->data() : nullptr,
              ignore != nullptr ? ignore->channels() : 0, display.pixelCount());
    return count.fraction();
}

void ClippedPixels::add(const float* display, int channels, const float* ignore, int ignoreChannels,
                        std::size_t pixels) {
    const float white = displayWhiteLevel();
    const int colourChannels = channels == 2 ? 1 : std::min(channels, 3);
    // An ignore image of fewer than 3 channels reads as grey (Image::rgb).
    const int ignoreColours = ignoreChannels < 3 ? 1 : 3;
    for (std::size_t i = 0; i < pixels; ++i) {
        if (ignore != nullptr) {
            const float* v = ignore + i * static_cast<std::size_t>(ignoreChannels);
            bool lit = false;
            for (int c = 0; c < ignoreColours; ++c) lit = lit || v[c] > 0.0f;
            if (lit) continue;
        }
        ++counted;
        const float* p = display + i * static_cast<std::size_t>(channels);
        for (int c = 0; c < colourChannels; ++c) {
            if (p[c] >= white) {
                ++clipped;
                break;
            }
        }
    }
}

double ClippedPixels::fraction() const {
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
