// Analytic sky models of voxel scenes (skyColor in shading.h). The gradient ones set ShadeOptions'
// skyTop and skyHorizon: L(ω) = horizon + (top − horizon) · max(0, ω_y), the horizon radiance at
// and below the horizon. The Preetham clear sky depends on the sun and is its own model
// (ShadeOptions::SkyModel::Preetham). docs/algorithms/voxel-path-tracing.md, "Sky".
#pragma once

#include <array>

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

// The turbidities the Preetham model was fitted for (Preetham, Shirley & Smits 1999, §3).
inline constexpr double kPreethamMinTurbidity = 2.0;
inline constexpr double kPreethamMaxTurbidity = 10.0;

// The Preetham clear sky for a turbidity (clamped to the range above) and a direction towards the
// sun (any length; a sun below the horizon is taken at it, where the model ends), scaled so that
// the zenith's luminance is `zenithLuminance`: the Perez coefficients A..E of luminance Y and
// chromaticities x and y (Appendix A.2), and each quantity's zenith value (Y = zenithLuminance;
// x, y from Appendix A.2's polynomials) over its Perez F(0, θs). What skyColor evaluates on both
// backends (shared/sky_preetham.h).
struct PreethamCoefficients {
    std::array<float, 5> luminance, x, y;
    std::array<float, 3> zenithOverF0;  // Y, x, y
};
PreethamCoefficients preethamSky(double turbidity, Vec3 sunDirection, double zenithLuminance);

}  // namespace luxel::voxel
