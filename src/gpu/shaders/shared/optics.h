// Optics of voxel surfaces, shared by the CPU renderer (src/voxel/shading_physical.cpp) and the
// GPU one (voxel_shading.glsl): vector Snell refraction with the total-internal-reflection test,
// the exact unpolarised dielectric Fresnel factor and Schlick's approximation, and the GGX and
// normalised Blinn-Phong specular lobes. Dot products and square roots only: no trigonometry
// (docs/algorithms/voxel-surfaces.md).
#ifndef LUXEL_GPU_SHARED_OPTICS_H
#define LUXEL_GPU_SHARED_OPTICS_H

#include "glsl_compat.h"

#define LUXEL_OPTICS_PI 3.14159265358979f

LUXEL_SHARED_BEGIN

// Mirror direction of i about the unit normal n.
LUXEL_FUNC vec3 opticsReflect(vec3 i, vec3 n) {
    return i - n * (2.0f * dot(n, i));
}

// Snell in vector form (GLSL refract): cosI = -dot(n, i) with n facing the incident side, eta =
// n_i / n_t. Returns k = cos^2(theta_t); k < 0 is total internal reflection (sin theta_i > n_t /
// n_i, so the critical angle is never computed).
LUXEL_FUNC float opticsRefractK(float cosI, float eta) {
    return 1.0f - eta * eta * (1.0f - cosI * cosI);
}

// The refracted unit direction for k >= 0: eta i + (eta cosI - sqrt(k)) n.
LUXEL_FUNC vec3 opticsRefract(vec3 i, vec3 n, float eta, float cosI, float k) {
    return i * eta + n * (eta * cosI - sqrt(k));
}

// Exact unpolarised Fresnel reflectance of a dielectric interface (pbrt's FrDielectric) for the
// cosines on the incident (n_i) and transmitted (n_t) sides.
LUXEL_FUNC float fresnelDielectricCosines(float cosI, float cosT, float nI, float nT) {
    const float rs = (nI * cosI - nT * cosT) / (nI * cosI + nT * cosT);
    const float rp = (nT * cosI - nI * cosT) / (nT * cosI + nI * cosT);
    return clamp(0.5f * (rs * rs + rp * rp), 0.0f, 1.0f);
}

// The same from the incident cosine alone; 1 under total internal reflection.
LUXEL_FUNC float fresnelDielectricExact(float cosI, float nI, float nT) {
    cosI = clamp(cosI, 0.0f, 1.0f);
    const float k = opticsRefractK(cosI, nI / nT);
    if (k < 0.0f) return 1.0f;
    return fresnelDielectricCosines(cosI, sqrt(k), nI, nT);
}

// Reflectance at normal incidence, ((n_i - n_t) / (n_i + n_t))^2 (0.04 for glass in air).
LUXEL_FUNC float fresnelF0(float nI, float nT) {
    const float r = (nI - nT) / (nI + nT);
    return r * r;
}

// Schlick: F0 + (1 - F0)(1 - cos)^5 for a given cosine.
LUXEL_FUNC float fresnelSchlick(float f0, float cosine) {
    const float m = clamp(1.0f - cosine, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

LUXEL_FUNC vec3 fresnelSchlickRgb(vec3 f0, float cosine) {
    const float m = clamp(1.0f - cosine, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (vec3(1.0f) - f0) * (m2 * m2 * m);
}

// Schlick for a dielectric interface with the cosine on the less dense side: cosI going into the
// denser medium, cosT = sqrt(k) coming out of it (F = 1 under total internal reflection). With
// cosI on the dense side the error reaches 0.96 near the critical angle.
LUXEL_FUNC float fresnelDielectricSchlick(float cosI, float nI, float nT) {
    cosI = clamp(cosI, 0.0f, 1.0f);
    float cosine = cosI;
    if (nI > nT) {
        const float k = opticsRefractK(cosI, nI / nT);
        if (k < 0.0f) return 1.0f;
        cosine = sqrt(k);
    }
    return fresnelSchlick(fresnelF0(nI, nT), cosine);
}

// GGX / Trowbridge-Reitz normal distribution (Walter et al. 2007), alpha = roughness^2.
LUXEL_FUNC float ggxD(float nh, float alpha) {
    const float a2 = alpha * alpha;
    const float f = nh * nh * (a2 - 1.0f) + 1.0f;
    return a2 / (LUXEL_OPTICS_PI * f * f);
}

// Height-correlated Smith visibility G / (4 N.L N.V) for GGX, in the form of "Physically Based
// Rendering in Filament".
LUXEL_FUNC float ggxSmithVisibility(float nv, float nl, float alpha) {
    const float a2 = alpha * alpha;
    const float gv = nl * sqrt(nv * nv * (1.0f - a2) + a2);
    const float gl = nv * sqrt(nl * nl * (1.0f - a2) + a2);
    const float s = gv + gl;
    return s > 0.0f ? 0.5f / s : 0.0f;
}

// Blinn-Phong exponent with the same highlight width as GGX of this alpha: n = 2 / alpha^2 - 2
// (Walter et al. 2007, Beckmann-Phong correspondence).
LUXEL_FUNC float blinnPhongExponent(float alpha) {
    return max(2.0f / (alpha * alpha) - 2.0f, 0.0f);
}

// Normalised Blinn-Phong lobe (n + 8) / (8 pi) (N.H)^n (Giesen 2009), without the Fresnel factor.
LUXEL_FUNC float blinnPhongLobe(float nh, float exponent) {
    return (exponent + 8.0f) / (8.0f * LUXEL_OPTICS_PI) * pow(max(nh, 0.0f), exponent);
}

LUXEL_SHARED_END

#endif
