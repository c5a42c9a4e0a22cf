// Shading terms of the voxel renderer both backends run (src/voxel/shading.cpp on the CPU,
// voxel_shading.glsl on the GPU): the face term of the Unity voxel ray tracer, the sky gradient,
// the procedural face texture with its 32-bit hash, texel addressing, and the running-average
// reflection weighting. Everything here is float and integer arithmetic, so both backends compute
// the same bits.
#ifndef LUXEL_GPU_SHARED_VOXEL_SHADING_H
#define LUXEL_GPU_SHARED_VOXEL_SHADING_H

#include "glsl_compat.h"
#include "optics.h"

// Specular models of physical lighting (VoxelRenderParams.specular, ShadeOptions::Specular).
#define LUXEL_VOXEL_SPECULAR_NONE 0
#define LUXEL_VOXEL_SPECULAR_BLINN_PHONG 1
#define LUXEL_VOXEL_SPECULAR_GGX 2

LUXEL_SHARED_BEGIN

// Wellons' "lowbias32" integer hash.
LUXEL_FUNC uint voxelMixHash(uint h) {
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    return h ^ (h >> 16u);
}

// The face term min((dot(n, sun) + 1) / 2 + ambient, 1); in shadow dot(n, sun) is clamped to 0.
// `sun` is used as given (not normalised), like the Unity tracer's (0, 1, 0.5).
LUXEL_FUNC float voxelFaceFactor(ivec3 normal, vec3 sun, float ambient, bool inShadow) {
    float d = float(normal.x) * sun.x + float(normal.y) * sun.y + float(normal.z) * sun.z;
    if (inShadow) d = min(d, 0.0f);
    return min((d + 1.0f) * 0.5f + ambient, 1.0f);
}

// The sky: horizon colour blended towards the top colour by the direction's height s in [0, 1].
LUXEL_FUNC vec3 voxelSkyColor(vec3 horizon, vec3 top, float s) {
    return horizon + (top - horizon) * s;
}

// Texel column (or row from the bottom) of face coordinate u in [0, 1) on `size` texels.
LUXEL_FUNC int voxelTexelIndex(float u, int size) {
    return clamp(int(u * float(size)), 0, size - 1);
}

// The procedural face texture: a per-texel brightness in [1 - strength, 1] from a hash of the
// voxel, its face and the texel under (u, v) on a grid of `texels` per side.
LUXEL_FUNC float voxelTextureFactor(ivec3 voxel, ivec3 normal, float u, float v, int texels,
                                    float strength) {
    const int n = max(texels, 1);
    const int tu = min(int(u * float(n)), n - 1);
    const int tv = min(int(v * float(n)), n - 1);
    uint h = voxelMixHash(uint(voxel.x) * 0x9e3779b9u);
    h = voxelMixHash(h ^ uint(voxel.y));
    h = voxelMixHash(h ^ uint(voxel.z));
    h = voxelMixHash(h ^ uint((normal.x + 1) * 9 + (normal.y + 1) * 3 + (normal.z + 1)));
    h = voxelMixHash(h ^ (uint(tu) << 16u) ^ uint(tv));
    const float noise = float(h >> 8u) / float(1 << 24);  // [0, 1)
    return 1.0f - clamp(strength, 0.0f, 1.0f) * noise;
}

// The Unity tracer's running average over reflections: hit k (1-based, k >= 2) adds colour / k,
// then the sum is scaled by k / (k + 1).
LUXEL_FUNC vec3 voxelRunningAverage(vec3 sum, vec3 colour, int k) {
    return (sum + colour * (1.0f / float(k))) * (float(k) / float(k + 1));
}

// Physical lighting (docs/algorithms/voxel-surfaces.md).

// The share of a surface's environment reflection traced as a mirror ray: 1 up to roughness 0.1,
// 0 from 0.3 on. Rougher surfaces show the sky's colour in the reflected direction instead, so
// rough ground mirrors no towers.
LUXEL_FUNC float voxelMirrorWeight(float roughness) {
    return clamp((0.3f - roughness) * 5.0f, 0.0f, 1.0f);
}

// Schlick with a roughness-limited grazing reflectance, F0 + (max(1 - roughness, F0) - F0)
// (1 - cos)^5 (Lagarde's fit for the environment seen by rough surfaces).
LUXEL_FUNC vec3 voxelRoughFresnel(vec3 f0, float cosine, float roughness) {
    const float m = clamp(1.0f - cosine, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (max(vec3(1.0f - roughness), f0) - f0) * (m2 * m2 * m);
}

// The specular BRDF f_s (Fresnel included, N.L not) for the sun direction l, seen along v.
LUXEL_FUNC vec3 voxelSpecularBrdf(int model, vec3 n, vec3 v, vec3 l, float alpha, vec3 f0) {
    const float nl = dot(n, l);
    const float nv = dot(n, v);
    if (model == LUXEL_VOXEL_SPECULAR_NONE || nl <= 0.0f || nv <= 0.0f) return vec3(0.0f);
    const vec3 h = normalize(l + v);
    const float nh = max(dot(n, h), 0.0f);
    const vec3 f = fresnelSchlickRgb(f0, max(dot(v, h), 0.0f));
    if (model == LUXEL_VOXEL_SPECULAR_GGX) {
        return f * (ggxD(nh, alpha) * ggxSmithVisibility(nv, nl, alpha));
    }
    return f * blinnPhongLobe(nh, blinnPhongExponent(alpha));
}

// Sunlight and sky light reflected towards v: the diffuse part diffuseAlbedo / pi (E_ambient +
// E_sun V N.L) plus the specular f_s E_sun V N.L. V is pure visibility; N.L is applied here,
// once, outside it.
LUXEL_FUNC vec3 voxelSurfaceLight(vec3 diffuseAlbedo, vec3 f0, float alpha, int specularModel,
                                  vec3 n, vec3 v, vec3 l, vec3 sunIrradiance, float visibility,
                                  vec3 ambientIrradiance) {
    const float nl = max(dot(n, l), 0.0f);
    const vec3 direct = sunIrradiance * (visibility * nl);
    vec3 result = diffuseAlbedo * (ambientIrradiance + direct) * (1.0f / LUXEL_OPTICS_PI);
    if (nl > 0.0f && visibility > 0.0f) {
        result = result + voxelSpecularBrdf(specularModel, n, v, l, alpha, f0) * direct;
    }
    return result;
}

// Beer-Lambert transmittance exp(-sigma_a d) over a path of length d inside a medium.
LUXEL_FUNC vec3 voxelTransmittance(vec3 sigmaA, float d) {
    return vec3(exp(-sigmaA.x * d), exp(-sigmaA.y * d), exp(-sigmaA.z * d));
}

LUXEL_SHARED_END

#endif
