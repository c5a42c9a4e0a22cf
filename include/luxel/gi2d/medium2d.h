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
    // Light that bounces (docs/algorithms/scattering-2d.md); both 3 channels in [0, 1), or empty
    // (0x0) when nothing in the scene re-emits light.
    //  - scattering: single-scattering albedo of the medium; a pixel re-emits scattering * fluence
    //    isotropically.
    //  - reflectance: diffuse reflectance of opaque surfaces; an opaque pixel re-emits reflectance
    //    times the radiance arriving at it from its transparent neighbours.
    Image scattering = {};
    Image reflectance = {};

    int width() const { return emission.width(); }
    int height() const { return emission.height(); }
    bool bounces() const { return !scattering.empty() || !reflectance.empty(); }
};

// Bytes a Medium2D of this size holds.
constexpr std::uint64_t mediumBytes(std::uint64_t width, std::uint64_t height) {
    return imageBytes(width, height, 3) * 2;
}

}  // namespace luxel::gi2d
