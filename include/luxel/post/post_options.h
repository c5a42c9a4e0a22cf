// What happens to a rendered HDR image before it is shown: bloom, exposure and tone curve, and the
// internal render resolution with its upscaler (docs/algorithms/post-processing.md).
#pragma once

#include <optional>
#include <string_view>

#include "luxel/core/tonemap.h"

namespace luxel::post {

// Dual-filter bloom (bloom.h). strength 0 turns it off.
struct BloomSettings {
    float strength = 0.0f;      // out = (1 - strength) * in + strength * bloom, in [0, 1]
    int levels = 5;             // half-resolution levels in the chain (clamped to the image)
    bool karisAverage = false;  // firefly-resistant first downsample (not energy preserving)
};

enum class Upscaler {
    Bilinear,  // baseline
    Edge,      // edge-aware kernel (upscale.h)
};

std::optional<Upscaler> parseUpscaler(std::string_view name);  // "bilinear" | "edge"
const char* upscalerName(Upscaler upscaler);

inline constexpr float kMinInternalScale = 0.25f;

struct PostOptions {
    BloomSettings bloom;
    ToneMapSettings tone;
    float internalScale = 1.0f;  // render at this fraction of the output size, in [0.25, 1]
    Upscaler upscaler = Upscaler::Edge;
    float sharpness = 0.0f;  // contrast-limited sharpening after upscaling, in [0, 1]
};

}  // namespace luxel::post
