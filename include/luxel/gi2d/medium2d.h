// The 2D participating medium every 2D solver works on (docs/conventions.md,
// docs/algorithms/pixel-medium.md).
//
// Per pixel: emission E (RGB radiance) and absorption sigma (RGB, per pixel length). A ray crossing
// a pixel over length l gets transmittance t = exp(-sigma * l) and radiance E * (1 - t); segments
// compose front to back: L = L_near + T_near * L_far, T = T_near * T_far.
#pragma once

#include <cstdint>

#include "luxel/core/image.h"
#include "luxel/core/vec.h"

namespace luxel::gi2d {

// Absorption is clamped to this per pixel length: exp(-64) ~ 1.6e-28 is black for every purpose
// and still a normal float, so no infinities reach the solvers.
inline constexpr float kMaxAbsorption = 64.0f;

struct Medium2D {
    Image emission;        // 3 channels, radiance
    Image absorption;      // 3 channels, per pixel length, in [0, kMaxAbsorption]
    Rgb boundaryRadiance;  // radiance arriving from outside the canvas

    int width() const { return emission.width(); }
    int height() const { return emission.height(); }
};

// Bytes a Medium2D of this size holds.
constexpr std::uint64_t mediumBytes(std::uint64_t width, std::uint64_t height) {
    return imageBytes(width, height, 3) * 2;
}

}  // namespace luxel::gi2d
