// Sun visibility on the GPU: the twin of SunVisibility::visibility (CPU:
// src/voxel/shadows/sun_visibility.cpp) for every method but Exact, from the arrays the CPU
// built (layout: shared/shadow_layout.h). The formulas are the shared ones (shadow_moments.h,
// soft_shadow.h); this file holds the lookups and the march loop.
//
// The includer may set the bindings before including (default: the render pass's 11..14):
// LUXEL_SHADOW_BINDING_PARAMS, _MOMENTS, _FIELD, _LEVELS.
#ifndef LUXEL_SUN_VISIBILITY_GLSL
#define LUXEL_SUN_VISIBILITY_GLSL

#include "shared/shadow_layout.h"
#include "shared/shadow_moments.h"
#include "shared/soft_shadow.h"

#ifndef LUXEL_SHADOW_BINDING_PARAMS
#define LUXEL_SHADOW_BINDING_PARAMS 11
#define LUXEL_SHADOW_BINDING_MOMENTS 12
#define LUXEL_SHADOW_BINDING_FIELD 13
#define LUXEL_SHADOW_BINDING_LEVELS 14
#endif

layout(std430, set = 0, binding = LUXEL_SHADOW_BINDING_PARAMS) readonly buffer ShadowParamsBuffer {
    ShadowParams shadow;
};
layout(std430, set = 0, binding = LUXEL_SHADOW_BINDING_MOMENTS) readonly buffer ShadowMoments {
    uint shadowMoments[];
};
layout(std430, set = 0, binding = LUXEL_SHADOW_BINDING_FIELD) readonly buffer ShadowField {
    float shadowField[];
};
layout(std430, set = 0, binding = LUXEL_SHADOW_BINDING_LEVELS) readonly buffer ShadowLevels {
    uint shadowLevels[];
};

ivec3 shadowWorldSize() {
    return ivec3(shadow.sizeX, shadow.sizeY, shadow.sizeZ);
}

// The stored field value of a cell, indices clamped into the world (DistanceField::cell).
float shadowFieldCell(ivec3 c) {
    ivec3 s = shadowWorldSize();
    c = clamp(c, ivec3(0), s - 1);
    return shadowField[(c.z * s.y + c.y) * s.x + c.x];
}

// DistanceField::cornerValue and cornerFeature: outside the world empty, no feature.
bool shadowOutside(ivec3 c) {
    return any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, shadowWorldSize()));
}

float shadowCornerValue(ivec3 c) {
    if (shadowOutside(c)) return LUXEL_SDF_FIELD_CAP;
    ivec3 s = shadowWorldSize();
    return shadowField[(c.z * s.y + c.y) * s.x + c.x];
}

uint shadowCornerFeature(ivec3 c) {
    if (shadowOutside(c)) return LUXEL_SDF_FEATURE_BASE;
    ivec3 s = shadowWorldSize();
    return floatBitsToUint(shadowField[s.x * s.y * s.z + (c.z * s.y + c.y) * s.x + c.x]);
}

// DistanceField::surfaceDistance: the nearest cube the 8 cells around p name.
float shadowSurfaceDistance(vec3 p) {
    ivec3 c0 = ivec3(floor(p - 0.5));
    bool inside = shadowCornerValue(ivec3(floor(p))) <= 0.0;
    float best = LUXEL_SDF_FIELD_CAP;
    for (int k = 0; k < 8; ++k) {
        ivec3 c = c0 + ivec3(k & 1, (k >> 1) & 1, k >> 2);
        best = min(best, sdfCornerCandidate(p, c, shadowCornerValue(c), shadowCornerFeature(c),
                                            inside, LUXEL_SDF_FIELD_CAP));
    }
    return inside ? -best : best;
}

// DistanceField::conservative.
float shadowFieldConservative(vec3 p) {
    ivec3 c = clamp(ivec3(floor(p)), ivec3(0), shadowWorldSize() - 1);
    float s = shadowFieldCell(c);
    if (s <= 0.0) return s;
    return (s + 0.5) - length(p - (vec3(c) + 0.5)) - 0.8660254037844386;
}

// DistanceField::estimate (trilinear).
float shadowFieldEstimate(vec3 p) {
    vec3 f = p - 0.5;
    ivec3 c0 = ivec3(floor(f));
    vec3 t = f - vec3(c0);
    float r = 0.0;
    for (int k = 0; k < 8; ++k) {
        ivec3 d = ivec3(k & 1, (k >> 1) & 1, k >> 2);
        vec3 w = mix(1.0 - t, t, vec3(d));
        r += w.x * w.y * w.z * shadowFieldCell(c0 + d);
    }
    return r;
}

// sdfSafeStep (src/voxel/shadows/sdf_shadow.cpp).
float shadowSafeStep(vec3 p, vec3 d) {
    float bound = shadowFieldConservative(p);
    ivec3 c = ivec3(floor(p));
    ivec3 s = shadowWorldSize();
    bool inside = all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, s));
    if (inside && shadowFieldCell(c) <= 0.0) return 0.0;
    float cellExit = LUXEL_INFINITY;
    for (int a = 0; a < 3; ++a) {
        if (d[a] > 0.0) cellExit = min(cellExit, (float(c[a] + 1) - p[a]) / d[a]);
        if (d[a] < 0.0) cellExit = min(cellExit, (float(c[a]) - p[a]) / d[a]);
    }
    return max(bound, cellExit + 1.0e-3);
}

// sdfSunVisibility: V and whether the march reached the sky or a full shadow.
float shadowSdf(vec3 origin, vec3 l, out bool valid) {
    vec3 s = vec3(shadowWorldSize());
    float tMax = LUXEL_INFINITY;
    for (int a = 0; a < 3; ++a) {
        if (l[a] > 0.0) tMax = min(tMax, (s[a] - origin[a]) / l[a]);
        if (l[a] < 0.0) tMax = min(tMax, -origin[a] / l[a]);
    }
    tMax = max(tMax, 0.0);
    float w = max(shadow.tanRadius, 1.0e-6);
    SdfShadowMarch m = sdfShadowBegin(0.0);
    bool cubes = (shadow.flags & LUXEL_SHADOW_SDF_CUBES) != 0u;
    valid = false;
    while (m.steps < int(shadow.sdfMaxSteps)) {
        if (m.t >= tMax) {
            valid = true;
            break;
        }
        vec3 p = origin + l * m.t;
        float h = cubes ? shadowSurfaceDistance(p) : shadowFieldEstimate(p);
        sdfShadowStep(m, h, shadowSafeStep(p, l), w);
        if (m.res <= LUXEL_SDF_RES_DONE) {
            valid = true;
            break;
        }
    }
    if (!valid && m.t >= tMax) valid = true;
    return sdfShadowVisibility(m.res);
}

vec4 shadowTexelMoments(int x, int y) {
    int i = y * shadow.mapSize + x;
    if ((shadow.flags & LUXEL_SHADOW_QUANTIZED) != 0u) {
        return unpackMoments16(shadowMoments[2 * i], shadowMoments[2 * i + 1]);
    }
    return vec4(uintBitsToFloat(shadowMoments[4 * i]), uintBitsToFloat(shadowMoments[4 * i + 1]),
                uintBitsToFloat(shadowMoments[4 * i + 2]),
                uintBitsToFloat(shadowMoments[4 * i + 3]));
}

// MomentShadowMap::visibility.
float shadowMoment(vec3 p, bool vsm, out bool valid) {
    vec3 l = vec3(shadow.lightX, shadow.lightY, shadow.lightZ);
    float mu = (dot(p, vec3(shadow.uX, shadow.uY, shadow.uZ)) - shadow.uMin) / shadow.texel;
    float mv = (dot(p, vec3(shadow.vX, shadow.vY, shadow.vZ)) - shadow.vMin) / shadow.texel;
    float n = float(shadow.mapSize);
    valid = mu >= 0.0 && mv >= 0.0 && mu <= n && mv <= n;
    if (!valid) return 1.0;
    float fu = mu - 0.5, fv = mv - 0.5;
    int x0 = int(floor(fu)), y0 = int(floor(fv));
    float tx = fu - float(x0), ty = fv - float(y0);
    vec4 b = vec4(0.0);
    for (int k = 0; k < 4; ++k) {
        int dx = k & 1, dy = k >> 1;
        vec4 m = shadowTexelMoments(clamp(x0 + dx, 0, shadow.mapSize - 1),
                                    clamp(y0 + dy, 0, shadow.mapSize - 1));
        b += m * ((dx != 0 ? tx : 1.0 - tx) * (dy != 0 ? ty : 1.0 - ty));
    }
    float z = (shadow.depthTop - dot(p, l)) / shadow.depthRange -
              shadow.depthBias / shadow.depthRange;
    return momentVisibility(b, z, vsm, shadow.momentBias, shadow.lightBleed);
}

// A hard shadow ray on the field's solid cells (value < 0), by Amanatides & Woo. Unlike the CPU's
// exact ray (castToSurface) it does not see cutout texels.
float shadowHard(vec3 origin, vec3 l) {
    ivec3 s = shadowWorldSize();
    ivec3 c = ivec3(floor(origin));
    ivec3 stp = ivec3(sign(l));
    vec3 inv = 1.0 / l;
    vec3 next;
    for (int a = 0; a < 3; ++a) {
        next[a] = stp[a] == 0 ? LUXEL_INFINITY
                              : (float(c[a] + (stp[a] > 0 ? 1 : 0)) - origin[a]) * inv[a];
    }
    for (int i = 0; i < s.x + s.y + s.z + 3; ++i) {
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, s))) return 1.0;
        if (shadowFieldCell(c) < 0.0) return 0.0;
        int a = next.x <= next.y && next.x <= next.z ? 0 : (next.y <= next.z ? 1 : 2);
        c[a] += stp[a];
        next[a] = (float(c[a] + (stp[a] > 0 ? 1 : 0)) - origin[a]) * inv[a];
    }
    return 1.0;
}

// V of the sun at a point on a voxel face (normal: the face's axis normal), footprint: camera
// distance for primary rays, ray-cone width per voxel for secondary ones.
float sunVisibility(vec3 point, ivec3 normal, float footprint) {
    vec3 l = vec3(shadow.lightX, shadow.lightY, shadow.lightZ);
    vec3 n = vec3(normal);
    if (dot(n, l) <= 0.0) return 0.0;
    vec3 o = point + n * shadow.normalOffset;
    uint method = shadow.method;
    bool valid;
    if (method == LUXEL_SHADOW_HARD) return shadowHard(point + n * 1.0e-3, l);
    if (method == LUXEL_SHADOW_MSM || method == LUXEL_SHADOW_VSM) {
        float v = shadowMoment(o, method == LUXEL_SHADOW_VSM, valid);
        return valid ? v : 1.0;
    }
    vec3 os = point + n * shadow.sdfNormalOffset;
    if (method == LUXEL_SHADOW_SDF) return shadowSdf(os, l, valid);
    if (method == LUXEL_SHADOW_FLOOD) {
        ivec3 c = ivec3(floor(point + n * 0.5));
        ivec3 s = shadowWorldSize();
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, s))) return 1.0;
        int i = (c.z * s.y + c.y) * s.x + c.x;
        return float((shadowLevels[i >> 2] >> (8 * (i & 3))) & 255u) / 15.0;
    }
    if (method == LUXEL_SHADOW_BLEND) {
        bool sdfNear = (shadow.flags & LUXEL_SHADOW_SDF_NEAR) != 0u;
        float a0 = mrmaWeight(footprint, shadow.blendNear, shadow.blendFar, sdfNear, true, true);
        bool sdfValid = true, msmValid = true;
        float vSdf = 1.0, vMsm = 1.0;
        if (a0 < 1.0) vSdf = shadowSdf(os, l, sdfValid);
        if (a0 > 0.0 || !sdfValid) vMsm = shadowMoment(o, false, msmValid);
        float a = mrmaWeight(footprint, shadow.blendNear, shadow.blendFar, sdfNear, sdfValid,
                             msmValid);
        if (a >= 1.0 && !msmValid) return vSdf;
        return mrmaCombine(vMsm, vSdf, a, (shadow.flags & LUXEL_SHADOW_MIN_IN_BAND) != 0u);
    }
    return 1.0;
}

#endif
