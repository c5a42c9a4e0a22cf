// The Preetham clear sky (Preetham, Shirley & Smits 1999, "A Practical Analytic Model for
// Daylight", §3 and Appendix A.2), evaluated by both backends: skyColor in src/voxel/shading.cpp
// and voxel_shading.glsl. The coefficients depend on the turbidity and the sun alone, so the CPU
// computes them once (preethamSky, luxel/voxel/sky_model.h) and both evaluate the same floats.
// docs/algorithms/voxel-path-tracing.md, "Sky".
#ifndef LUXEL_GPU_SHARED_SKY_PREETHAM_H
#define LUXEL_GPU_SHARED_SKY_PREETHAM_H

#include "glsl_compat.h"

// VoxelRenderParams.skyModel, ShadeOptions::SkyModel.
#define LUXEL_SKY_GRADIENT 0u
#define LUXEL_SKY_PREETHAM 1u

// Below this cos θ the Perez term exp(B / cos θ) is taken at it: the horizon's value (B < 0 for
// every turbidity the model accepts, so the term is 0 there to float precision).
#define LUXEL_SKY_MIN_COS_THETA 1e-3f

LUXEL_SHARED_BEGIN

// The Perez et al. (1993) distribution's five coefficients for one quantity (Y, x or y).
struct SkyPerez {
    float a, b, c, d, e;
};

// One clear sky: the Perez coefficients of luminance Y and chromaticities x and y, and each
// quantity's zenith value over its Perez F(0, θs), so that quantity(θ, γ) = zenith · F(θ, γ).
struct PreethamSky {
    SkyPerez luminance;
    SkyPerez x;
    SkyPerez y;
    vec3 zenithOverF0;  // (Y, x, y)
};

// Perez's F(θ, γ) = (1 + A e^(B / cos θ)) (1 + C e^(D γ) + E cos² γ) (Preetham Eq. 3).
LUXEL_FUNC float skyPerezF(SkyPerez p, float cosTheta, float gamma, float cosGamma) {
    return (1.0f + p.a * exp(p.b / cosTheta)) *
           (1.0f + p.c * exp(p.d * gamma) + p.e * cosGamma * cosGamma);
}

// The sky's linear sRGB radiance along the unit direction `w` for the unit sun direction `sun`
// (y up). At and below the horizon: the horizon's radiance at the same angle γ from the sun.
LUXEL_FUNC vec3 preethamSkyColor(PreethamSky s, vec3 w, vec3 sun) {
    const float cosTheta = max(w.y, LUXEL_SKY_MIN_COS_THETA);
    const float cosGamma = clamp(dot(w, sun), -1.0f, 1.0f);
    const float gamma = acos(cosGamma);
    const float lum = s.zenithOverF0.x * skyPerezF(s.luminance, cosTheta, gamma, cosGamma);
    const float cx = s.zenithOverF0.y * skyPerezF(s.x, cosTheta, gamma, cosGamma);
    const float cy = s.zenithOverF0.z * skyPerezF(s.y, cosTheta, gamma, cosGamma);
    // xyY to CIE XYZ, then to linear sRGB (IEC 61966-2-1, D65 white), whose luminance is Y.
    const float bigX = cx / cy * lum;
    const float bigZ = (1.0f - cx - cy) / cy * lum;
    const float r = 3.2404542f * bigX - 1.5371385f * lum - 0.4985314f * bigZ;
    const float g = -0.9692660f * bigX + 1.8760108f * lum + 0.0415560f * bigZ;
    const float b = 0.0556434f * bigX - 0.2040259f * lum + 1.0572252f * bigZ;
    return vec3(max(r, 0.0f), max(g, 0.0f), max(b, 0.0f));
}

LUXEL_SHARED_END

#endif
