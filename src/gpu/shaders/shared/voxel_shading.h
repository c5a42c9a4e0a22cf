// Shading terms of the voxel renderer both backends run (src/voxel/shading.cpp on the CPU,
// voxel_shading.glsl on the GPU): the face term of the Unity voxel ray tracer, the sky gradient,
// the procedural face texture with its 32-bit hash, texel addressing, and the running-average
// reflection weighting. Everything here is float and integer arithmetic, so both backends compute
// the same bits.
#ifndef LUXEL_GPU_SHARED_VOXEL_SHADING_H
#define LUXEL_GPU_SHARED_VOXEL_SHADING_H

#include "glsl_compat.h"

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

LUXEL_SHARED_END

#endif
