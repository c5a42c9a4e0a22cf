// Moment shadow map math, compiled as C++ and GLSL (glsl_compat.h): the variance bound (VSM), the
// 4-moment Hamburger MSM and the 16-bit optimized moment quantization. Depth z is linear
// light-space depth in [0, 1] (0 nearest the light). Every function returns V, the lit fraction.
//
// Based on:
// - Donnelly & Lauritzen, "Variance Shadow Maps", I3D 2006: V <= p_max = s2 / (s2 + (z - mu)^2) for
//   z > mu (one-sided Chebyshev, Cantelli). The MRMA design note prints the reciprocal of this
//   bound and a missing square in s2; see docs/algorithms/voxel-shadows.md.
// - Peters & Klein, "Moment Shadow Mapping", I3D 2015 (author's corrected version: the algorithm
//   returns 1 - w1): Hamburger 4MSM by a closed-form 3x3 Cholesky solve, moment bias towards
//   (0.5, 0.5, 0.5, 0.5), and the optimized affine quantization for 4 x 16 bit (section 4.3).
#ifndef LUXEL_GPU_SHARED_SHADOW_MOMENTS_H
#define LUXEL_GPU_SHARED_SHADOW_MOMENTS_H

#include "glsl_compat.h"

// Default moment bias alpha per storage: fp32 keeps the Hankel matrix regular with a tiny bias;
// 16-bit storage needs a larger one to absorb its rounding (Peters & Klein 2015, section 4.3).
#define LUXEL_MSM_BIAS_FP32 3.0e-6f
#define LUXEL_MSM_BIAS_16BIT 6.0e-5f
// Smallest variance VSM accepts (keeps the bound finite on flat receivers).
#define LUXEL_VSM_MIN_VARIANCE 1.0e-6f
// Constant added to the first optimized moment (Peters & Klein 2015, section 4.3).
#define LUXEL_MSM_OPTIMIZED_OFFSET 0.035955884801f

LUXEL_SHARED_BEGIN

// (z, z^2, z^3, z^4): the moments of one depth sample.
LUXEL_FUNC vec4 momentsOfDepth(float z) {
    float z2 = z * z;
    return vec4(z, z2, z2 * z, z2 * z2);
}

LUXEL_FUNC float shadowLinstep(float lo, float hi, float v) {
    return clamp((v - lo) / (hi - lo), 0.0f, 1.0f);
}

// Light-bleeding reduction: linstep(rho, 1, V) cuts the bound's tail (rho = 0: unchanged).
LUXEL_FUNC float reduceLightBleed(float v, float rho) {
    return rho > 0.0f ? shadowLinstep(rho, 1.0f, v) : v;
}

// VSM: mean m1 and second moment m2 of the filtered depths, receiver depth z. The one-sided
// Chebyshev bound p_max is an upper bound on the lit fraction P(z_occluder >= z).
LUXEL_FUNC float vsmVisibility(float m1, float m2, float z) {
    if (z <= m1) return 1.0f;
    float variance = max(m2 - m1 * m1, LUXEL_VSM_MIN_VARIANCE);
    float d = z - m1;
    return variance / (variance + d * d);
}

// The moments biased by alpha towards 0.5 (Peters & Klein 2015, moment bias).
LUXEL_FUNC vec4 msmBiased(vec4 moments, float alpha) {
    return moments * (1.0f - alpha) + vec4(0.5f) * alpha;
}

// The other two support points z2 <= z3 of the canonical three-atom representation of the
// biased moments b with an atom at zf: the roots of c1 + c2 z + c3 z^2 where B c = (1, zf, zf^2).
LUXEL_FUNC vec2 msmSupport(vec4 b, float zf) {
    // LDL^T of the Hankel matrix [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]]. The bias keeps it
    // positive definite; the floors only catch fp32 rounding of nearly singular moments.
    float d22 = max(b.y - b.x * b.x, 1.0e-12f);
    float l32 = (b.z - b.x * b.y) / d22;
    float d33 = max((b.w - b.y * b.y) - l32 * l32 * d22, 1.0e-14f);
    // Solve B c = (1, zf, zf^2).
    float y2 = zf - b.x;
    float y3 = zf * zf - b.y - l32 * y2;
    float c3 = y3 / d33;
    float c2 = y2 / d22 - l32 * c3;
    float c1 = 1.0f - b.x * c2 - b.y * c3;
    // The cancellation-free quadratic formula: with c3 near 0 (a nearly two-atom distribution in
    // fp32) one root goes far outside [0, 1] and stays finite.
    if (abs(c3) < 1.0e-20f) c3 = c3 < 0.0f ? -1.0e-20f : 1.0e-20f;
    float s = sqrt(max(c2 * c2 - 4.0f * c1 * c3, 0.0f));
    float k = -0.5f * (c2 + (c2 < 0.0f ? -s : s));
    float ra = k / c3;
    float rb = abs(k) > 0.0f ? c1 / k : ra;
    return vec2(min(ra, rb), max(ra, rb));
}

// Hamburger 4MSM: the shadow intensity G (occluded fraction), the sharpest lower bound consistent
// with the four moments b, at receiver depth zf, after biasing b by alpha towards 0.5.
LUXEL_FUNC float msmShadowIntensity(vec4 moments, float zf, float alpha) {
    vec4 b = msmBiased(moments, alpha);
    vec2 support = msmSupport(b, zf);
    float z2 = support.x;
    float z3 = support.y;
    if (zf <= z2) return 0.0f;
    if (zf <= z3) return (zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2));
    return 1.0f - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((zf - z2) * (zf - z3));
}

// The mean depth of the occluders in front of zf: the atoms below zf of the same canonical
// three-atom distribution (support zf, z2, z3) msmShadowIntensity reads G from, weighted by
// their weights (Vandermonde solve). Returns (G, mean blocker depth); G = 0 means no blocker
// and the depth is then zf. The blocker search of moment soft shadow mapping (Peters et al.,
// "Beyond hard shadows: moment shadow maps for single scattering, soft shadows and
// translucent occluders", I3D 2016) in its simplest form.
LUXEL_FUNC vec2 msmBlocker(vec4 moments, float zf, float alpha) {
    vec4 b = msmBiased(moments, alpha);
    vec2 support = msmSupport(b, zf);
    float z2 = support.x;
    float z3 = support.y;
    if (zf <= z2) return vec2(0.0f, zf);
    // Weights of z2 and z3: the Vandermonde system sum w = 1, sum w z = b1, sum w z^2 = b2.
    float w2 = (zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2));
    if (zf <= z3) return vec2(clamp(w2, 0.0f, 1.0f), clamp(z2, 0.0f, zf));
    float w3 = (zf * z2 - b.x * (zf + z2) + b.y) / ((z3 - zf) * (z3 - z2));
    w2 = max(w2, 0.0f);
    w3 = max(w3, 0.0f);
    float g = w2 + w3;
    if (g <= 0.0f) return vec2(0.0f, zf);
    return vec2(min(g, 1.0f), clamp((w2 * z2 + w3 * z3) / g, 0.0f, zf));
}

// V of the Hamburger 4MSM: 1 - clamp(G).
LUXEL_FUNC float msmVisibility(vec4 moments, float zf, float alpha) {
    return 1.0f - clamp(msmShadowIntensity(moments, zf, alpha), 0.0f, 1.0f);
}

// The optimized quantization (Peters & Klein 2015, section 4.3): an affine map of the moments
// whose image of the valid moments fits [0, 1] with the rounding error spread evenly, so 4 x 16
// bit UNORM keeps the shadow close to fp32. The matrices are the paper's (rows: input moment).
LUXEL_FUNC vec4 msmEncodeOptimized(vec4 b) {
    return vec4(
        -2.07224649f * b.x + 32.23703778f * b.y - 68.571074599f * b.z + 39.3703274134f * b.w +
            LUXEL_MSM_OPTIMIZED_OFFSET,
        13.7948857237f * b.x - 59.4683975703f * b.y + 82.0359750338f * b.z - 35.364903257f * b.w,
        0.105877704f * b.x - 1.9077466311f * b.y + 9.3496555107f * b.z - 6.6543490743f * b.w,
        9.7924062118f * b.x - 33.7652110555f * b.y + 47.9456096605f * b.z - 23.9728048165f * b.w);
}

LUXEL_FUNC vec4 msmDecodeOptimized(vec4 q) {
    float q0 = q.x - LUXEL_MSM_OPTIMIZED_OFFSET;
    return vec4(
        0.2227744146f * q0 + 0.0771972861f * q.y + 0.7926986636f * q.z + 0.0319417555f * q.w,
        0.1549679261f * q0 + 0.1394629426f * q.y + 0.7963415838f * q.z - 0.1722823173f * q.w,
        0.1451988946f * q0 + 0.2120202157f * q.y + 0.7258694464f * q.z - 0.2758014811f * q.w,
        0.163127443f * q0 + 0.2591432266f * q.y + 0.6539092497f * q.z - 0.3376131734f * q.w);
}

// One 16-bit UNORM value as the GPU's packUnorm2x16 rounds it.
LUXEL_FUNC uint quantizeUnorm16(float v) {
    return uint(floor(clamp(v, 0.0f, 1.0f) * 65535.0f + 0.5f));
}

LUXEL_FUNC float dequantizeUnorm16(uint q) {
    return float(q) / 65535.0f;
}

// The moments of one stored texel: fp32 words as float bits, or two words of 16-bit optimized
// moments (q0 | q1 << 16, q2 | q3 << 16), dequantized and decoded.
LUXEL_FUNC vec4 unpackMoments16(uint w0, uint w1) {
    return msmDecodeOptimized(vec4(dequantizeUnorm16(w0 & 0xffffu), dequantizeUnorm16(w0 >> 16u),
                                   dequantizeUnorm16(w1 & 0xffffu), dequantizeUnorm16(w1 >> 16u)));
}

// V from filtered moments at receiver depth z: Hamburger MSM or VSM, then light-bleed reduction.
LUXEL_FUNC float momentVisibility(vec4 b, float z, bool vsm, float alpha, float rho) {
    float v = vsm ? vsmVisibility(b.x, b.y, z) : msmVisibility(b, z, alpha);
    return reduceLightBleed(v, rho);
}

LUXEL_SHARED_END

#endif
