// Soft-shadow math shared by the CPU and GPU sun visibility (compiled as C++ and GLSL): the SDF
// march towards a disk light and the corrected MRMA blend of MSM and SDF visibility.
//
// Based on:
// - I. Quilez, "soft shadows in raymarched SDFs" (2010, improved 2018): the ratio h / t measures
// how
//   far a ray clears the nearest surface; S. Aaltonen's improvement (GDC 2018, Claybook) estimates
//   the closest approach between two samples, y = h^2 / (2 ph), d = sqrt(h^2 - y^2); Quilez's
//   negative extension lets res reach -1 (the ray penetrates thin occluders) and remaps it with
//   0.25 (1 + res)^2 (2 - res), which gives the inner half of the penumbra too. The light's
//   angular radius calibrates it: w = tan(theta_L).
// - The MRMA design note's blend, corrected: V = a V_msm + (1 - a) V_sdf with a in [0, 1] a
//   smoothstep of the footprint, validity overrides, and an optional min() inside the band.
//
// The march itself reads the distance field through the includer's lookups, so the loop is
// written by each side around sdfShadowStep (one step's formula lives here, once).
#ifndef LUXEL_GPU_SHARED_SOFT_SHADOW_H
#define LUXEL_GPU_SHARED_SOFT_SHADOW_H

#include "glsl_compat.h"

// Smallest step (voxels): the ray keeps moving inside occluders (negative extension).
#define LUXEL_SDF_MIN_STEP 0.05f
// res below this is fully shadowed (-1 within rounding): the march may stop.
#define LUXEL_SDF_RES_DONE (-0.999f)

// The distance field's feature words (DistanceField::features): the offset from a cell to its
// nearest voxel of the other kind (solid for empty cells, empty for solid ones), 7 bits a
// component (offset + 64), bit 21 set when present (within 63 cells), over the exponent bits of
// 1.0f, so the word read from the float field buffer is a normal float in [1, 2).
#define LUXEL_SDF_FEATURE_BASE 0x3F800000u
#define LUXEL_SDF_FEATURE_VALID 0x200000u
#define LUXEL_SDF_FEATURE_RANGE 63
// DistanceField::kCap: the clamp of the stored values, and the distance of a cell without feature.
#define LUXEL_SDF_FIELD_CAP 16.0f

LUXEL_SHARED_BEGIN

#ifdef __cplusplus
inline constexpr uint kSdfNoFeature = LUXEL_SDF_FEATURE_BASE;
#endif

LUXEL_FUNC uint packSdfFeature(ivec3 o) {
    if (abs(o.x) > LUXEL_SDF_FEATURE_RANGE || abs(o.y) > LUXEL_SDF_FEATURE_RANGE ||
        abs(o.z) > LUXEL_SDF_FEATURE_RANGE) {
        return LUXEL_SDF_FEATURE_BASE;
    }
    return LUXEL_SDF_FEATURE_BASE | LUXEL_SDF_FEATURE_VALID | uint(o.x + 64) |
           (uint(o.y + 64) << 7u) | (uint(o.z + 64) << 14u);
}

LUXEL_FUNC bool sdfFeatureValid(uint w) {
    return (w & LUXEL_SDF_FEATURE_VALID) != 0u;
}

LUXEL_FUNC ivec3 unpackSdfFeature(uint w) {
    return ivec3(int(w & 127u) - 64, int((w >> 7u) & 127u) - 64, int((w >> 14u) & 127u) - 64);
}

// Euclidean distance from p to the unit cube [c, c + 1].
LUXEL_FUNC float cubeDistance(vec3 p, ivec3 c) {
    float dx = max(max(float(c.x) - p.x, p.x - float(c.x + 1)), 0.0f);
    float dy = max(max(float(c.y) - p.y, p.y - float(c.y + 1)), 0.0f);
    float dz = max(max(float(c.z) - p.z, p.z - float(c.z + 1)), 0.0f);
    return sqrt(dx * dx + dy * dy + dz * dz);
}

// One corner cell's candidate for the distance from p to the nearest cube of the other kind than
// p's cell (inside: p lies in a solid cell): the corner's own cube when it is of the other kind,
// else the cube of its nearest feature (`cap` when it has none within range).
LUXEL_FUNC float sdfCornerCandidate(vec3 p, ivec3 c, float value, uint feature, bool inside,
                                    float cap) {
    bool cornerSolid = value <= 0.0f;
    if (cornerSolid != inside) return cubeDistance(p, c);
    if (!sdfFeatureValid(feature)) return cap;
    return cubeDistance(p, c + unpackSdfFeature(feature));
}

// State of one march from a receiver towards the light.
struct SdfShadowMarch {
    float res;   // running min of the clearance ratio, in [-1, 1]
    float t;     // distance along the ray (voxels)
    float ph;    // previous distance estimate (<= 0: none yet)
    float step;  // the last advance
    int steps;
};

LUXEL_FUNC SdfShadowMarch sdfShadowBegin(float tMin) {
    return SdfShadowMarch(1.0f, tMin, -1.0f, 0.0f, 0);
}

// One step: `h` is the distance estimate at the current sample (negative inside occluders),
// `stepDistance` a distance the ray may safely advance (a conservative lower bound), w = tan of
// the light's angular radius.
LUXEL_FUNC void sdfShadowStep(LUXEL_INOUT(SdfShadowMarch) m, float h, float stepDistance, float w) {
    float y = 0.0f;
    float d = h;
    if (h > 0.0f && m.ph > 0.0f && m.step > 0.0f) {
        // Aaltonen: the surface touches both spheres (radius ph at the previous sample, h here);
        // the closest approach lies where they intersect, y back along the ray. With the step s
        // equal to ph this is his y = h^2 / (2 ph); the march's steps may be shorter than ph.
        float s = m.step;
        float yc = (h * h - m.ph * m.ph + s * s) / (2.0f * s);
        if (yc > 0.0f && yc < h) {
            y = yc;
            d = sqrt(h * h - yc * yc);
        }
    }
    m.res = max(min(m.res, d / (w * max(m.t - y, 1.0e-4f))), -1.0f);
    m.ph = h;
    m.step = max(stepDistance, LUXEL_SDF_MIN_STEP);
    m.t += m.step;
    m.steps += 1;
}

// V from the clearance ratio: smoothstep over [-1, 1], so res = 0 (the ray grazes a silhouette)
// is half lit.
LUXEL_FUNC float sdfShadowVisibility(float res) {
    float r = clamp(res, -1.0f, 1.0f);
    return 0.25f * (1.0f + r) * (1.0f + r) * (2.0f - r);
}

LUXEL_FUNC float shadowSmoothstep(float e0, float e1, float x) {
    float s = clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return s * s * (3.0f - 2.0f * s);
}

// The MRMA weight a of V_msm, in [0, 1]: a smoothstep band over the footprint (camera distance for
// primary rays). sdfNear: SDF near the camera and MSM far, else the opposite split.
// Validity overrides: an invalid SDF march gives a = 1, an invalid MSM lookup a = 0.
LUXEL_FUNC float mrmaWeight(float footprint, float nearEdge, float farEdge, bool sdfNear,
                            bool sdfValid, bool msmValid) {
    float s = farEdge > nearEdge ? shadowSmoothstep(nearEdge, farEdge, footprint)
                                 : (footprint >= farEdge ? 1.0f : 0.0f);
    float a = sdfNear ? s : 1.0f - s;
    if (!msmValid) a = 0.0f;
    if (!sdfValid) a = 1.0f;
    return a;
}

// The blend: a V_msm + (1 - a) V_sdf, or min(V_msm, V_sdf) strictly inside the band when asked.
LUXEL_FUNC float mrmaCombine(float vMsm, float vSdf, float a, bool minInBand) {
    if (minInBand && a > 0.0f && a < 1.0f) return min(vMsm, vSdf);
    return clamp(a * vMsm + (1.0f - a) * vSdf, 0.0f, 1.0f);
}

LUXEL_SHARED_END

#endif
