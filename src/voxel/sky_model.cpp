// Analytic sky models: the overcast sky as a gradient, the Preetham clear sky's coefficients.
#include "luxel/voxel/sky_model.h"

#include <algorithm>
#include <cmath>

namespace luxel::voxel {

SkyGradient cieOvercastSky(Rgb zenith) {
    // cos θ is the direction's ω_y, the gradient's blend factor: Lz/3 + (Lz − Lz/3) ω_y.
    return {zenith, zenith * (1.0f / 3.0f)};
}

namespace {

// Perez's F(θ, γ) in double (Preetham Eq. 3).
double perezF(const std::array<double, 5>& p, double theta, double gamma) {
    const double cosGamma = std::cos(gamma);
    return (1.0 + p[0] * std::exp(p[1] / std::cos(theta))) *
           (1.0 + p[2] * std::exp(p[3] * gamma) + p[4] * cosGamma * cosGamma);
}

// A coefficient row of Appendix A.2: (slope, intercept) in the turbidity per coefficient.
std::array<double, 5> linearInTurbidity(const double (&rows)[5][2], double t) {
    std::array<double, 5> out{};
    for (int i = 0; i < 5; ++i) out[i] = rows[i][0] * t + rows[i][1];
    return out;
}

// A zenith chromaticity of Appendix A.2: [T², T, 1] · M · [θs³, θs², θs, 1].
double zenithChromaticity(const double (&m)[3][4], double t, double thetaSun) {
    const double powersT[3] = {t * t, t, 1.0};
    const double powersS[4] = {thetaSun * thetaSun * thetaSun, thetaSun * thetaSun, thetaSun, 1.0};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) sum += powersT[i] * m[i][j] * powersS[j];
    }
    return sum;
}

std::array<float, 5> toFloat(const std::array<double, 5>& p) {
    std::array<float, 5> out{};
    for (int i = 0; i < 5; ++i) out[i] = static_cast<float>(p[i]);
    return out;
}

}  // namespace

PreethamCoefficients preethamSky(double turbidity, Vec3 sunDirection, double zenithLuminance) {
    const double t = std::clamp(turbidity, kPreethamMinTurbidity, kPreethamMaxTurbidity);
    constexpr double kY[5][2] = {{0.1787, -1.4630},
                                 {-0.3554, 0.4275},
                                 {-0.0227, 5.3251},
                                 {0.1206, -2.5771},
                                 {-0.0670, 0.3703}};
    constexpr double kX[5][2] = {{-0.0193, -0.2592},
                                 {-0.0665, 0.0008},
                                 {-0.0004, 0.2125},
                                 {-0.0641, -0.8989},
                                 {-0.0033, 0.0452}};
    constexpr double kYc[5][2] = {{-0.0167, -0.2608},
                                  {-0.0950, 0.0092},
                                  {-0.0079, 0.2102},
                                  {-0.0441, -1.6537},
                                  {-0.0109, 0.0529}};
    constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                       {-0.02903, 0.06377, -0.03202, 0.00394},
                                       {0.11693, -0.21196, 0.06052, 0.25886}};
    constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                       {-0.04214, 0.08970, -0.04153, 0.00516},
                                       {0.15346, -0.26756, 0.06670, 0.26688}};
    const double length = std::sqrt(double(sunDirection.x) * sunDirection.x +
                                    double(sunDirection.y) * sunDirection.y +
                                    double(sunDirection.z) * sunDirection.z);
    const double up = length > 0.0 ? sunDirection.y / length : 1.0;
    // The sun's zenith angle, at most the horizon's.
    const double thetaSun = std::acos(std::clamp(up, 0.0, 1.0));
    const auto lum = linearInTurbidity(kY, t);
    const auto x = linearInTurbidity(kX, t);
    const auto y = linearInTurbidity(kYc, t);
    // At the zenith (θ = 0) the angle to the sun is θs.
    PreethamCoefficients c;
    c.luminance = toFloat(lum);
    c.x = toFloat(x);
    c.y = toFloat(y);
    c.zenithOverF0 = {
        static_cast<float>(zenithLuminance / perezF(lum, 0.0, thetaSun)),
        static_cast<float>(zenithChromaticity(kZenithX, t, thetaSun) / perezF(x, 0.0, thetaSun)),
        static_cast<float>(zenithChromaticity(kZenithY, t, thetaSun) / perezF(y, 0.0, thetaSun))};
    return c;
}

}  // namespace luxel::voxel
