// Analytic sky models of voxel scenes. Every model is a sky gradient (ShadeOptions' skyTop and
// skyHorizon, skyColor in shading.h): L(ω) = horizon + (top − horizon) · max(0, ω_y), the
// horizon radiance at and below the horizon. docs/algorithms/voxel-path-tracing.md
#pragma once

#include "luxel/core/vec.h"

namespace luxel::voxel {

// The radiance of a gradient sky straight up and at the horizon (linear RGB).
struct SkyGradient {
    Rgb top;
    Rgb horizon;
};

// The CIE standard overcast sky (Moon & Spencer 1942; CIE S 011/E:2003 sky type 1):
// L(θ) = Lz (1 + 2 cos θ) / 3 for the zenith angle θ, so top = Lz and horizon = Lz / 3. Its
// irradiance on a horizontal plane is 7π Lz / 9.
SkyGradient cieOvercastSky(Rgb zenith);

}  // namespace luxel::voxel
