// Post-processing arithmetic both backends run (docs/algorithms/post-processing.md): bilinear
// footprints with clamp-to-edge, the dual-filter bloom taps (Bjørge, SIGGRAPH 2015
// "Bandwidth-Efficient Rendering"), the Karis average, and the edge-aware upscaling kernel.
// Compiled as C++ by src/post/*.cpp and as GLSL by src/gpu/shaders/post/*.comp.glsl; the loops
// that fetch pixels are written in each (buffers differ), the formulas only here.
//
// Positions are in source texels with pixel corners at integers (texel i covers [i, i + 1]).
#ifndef LUXEL_GPU_SHARED_POST_KERNELS_H
#define LUXEL_GPU_SHARED_POST_KERNELS_H

#include "glsl_compat.h"

LUXEL_SHARED_BEGIN

// The 2 x 2 texels around position p of a w x h image, clamped to it, and the blend weights.
struct PostBilinear {
    int x0, x1, y0, y1;
    float tx, ty;
};

LUXEL_FUNC PostBilinear postBilinearAt(vec2 p, int w, int h) {
    const float u = p.x - 0.5f;
    const float v = p.y - 0.5f;
    const float fu = floor(u);
    const float fv = floor(v);
    const int ix = int(fu);
    const int iy = int(fv);
    return PostBilinear(clamp(ix, 0, w - 1), clamp(ix + 1, 0, w - 1), clamp(iy, 0, h - 1),
                        clamp(iy + 1, 0, h - 1), u - fu, v - fv);
}

// Where the centre of destination pixel (x, y) lies in the source image.
LUXEL_FUNC vec2 postSourcePosition(int x, int y, int srcW, int srcH, int dstW, int dstH) {
    return vec2((float(x) + 0.5f) * float(srcW) / float(dstW),
                (float(y) + 0.5f) * float(srcH) / float(dstH));
}

// The bloom chain is an exact factor-2 pyramid (level sides ceil(side / 2); an odd side's last
// texel reads past the edge, clamped): destination pixel (x, y) of a downsample sits at the shared
// corner of source texels 2x, 2x + 1; of an upsample, at a quarter texel inside low texel x / 2.
LUXEL_FUNC vec2 postDownPosition(int x, int y) {
    return vec2(2.0f * float(x) + 1.0f, 2.0f * float(y) + 1.0f);
}
LUXEL_FUNC vec2 postUpPosition(int x, int y) {
    return vec2((float(x) + 0.5f) * 0.5f, (float(y) + 0.5f) * 0.5f);
}

// Downsample taps (5): the centre x 4/8 and four diagonal taps x 1/8, offset by one
// source texel (half a destination texel) on each axis. Each tap, bilinear at a texel
// corner, is a 2 x 2 box; the five boxes each tile the source, so the mean is kept exactly away
// from the borders.
LUXEL_FUNC vec2 postDownTapOffset(int t) {
    if (t == 0) return vec2(0.0f);
    return vec2((t == 1 || t == 3) ? -1.0f : 1.0f, (t == 1 || t == 2) ? -1.0f : 1.0f);
}
LUXEL_FUNC float postDownTapWeight(int t) {
    return t == 0 ? 0.5f : 0.125f;
}

// Upsample taps (8), in half source texels: four diagonal (+-1, +-1) x 2/12 and four axial
// (+-2, 0), (0, +-2) x 1/12. Bilinear sampling at any fixed offset keeps the mean.
LUXEL_FUNC vec2 postUpTapOffset(int t) {
    if (t < 4) return vec2((t & 1) != 0 ? 1.0f : -1.0f, (t & 2) != 0 ? 1.0f : -1.0f);
    if (t == 4) return vec2(-2.0f, 0.0f);
    if (t == 5) return vec2(2.0f, 0.0f);
    if (t == 6) return vec2(0.0f, -2.0f);
    return vec2(0.0f, 2.0f);
}
LUXEL_FUNC float postUpTapWeight(int t) {
    return t < 4 ? 2.0f / 12.0f : 1.0f / 12.0f;
}

LUXEL_FUNC float postLuma(vec3 c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// Karis average (Karis 2013; Jimenez, SIGGRAPH 2014): taps weighted by 1 / (1 + luma), so one
// very bright texel cannot dominate a block (fireflies).
LUXEL_FUNC float postKarisWeight(vec3 c) {
    return 1.0f / (1.0f + max(postLuma(c), 0.0f));
}

// Edge-aware upscaling kernel, in the spirit of FSR 1 EASU: a radial window over the 4 x 4
// texels around the sample, stretched along the local edge (smooths stair steps) and with a
// sharper negative lobe across strong edges. `edge` in [0, 1] is the edge strength.
struct PostEdge {
    vec2 normal;  // unit gradient direction (across the edge)
    float edge;
    float lobe;  // lambda of postEdgeWindow
};

// The window over squared radius r2 < 4: (1 - r2/4)^2 (1 - lambda r2), zero beyond 2 texels,
// crossing zero at 1/sqrt(lambda).
LUXEL_FUNC float postEdgeWindow(float r2, float lambda) {
    if (r2 >= 4.0f) return 0.0f;
    const float a = 1.0f - 0.25f * r2;
    return a * a * (1.0f - lambda * r2);
}

// The gradient of the luma grid at inner texel (i, j) in 1..2, by central differences; the four
// rows are the lumas of texels (base - 1 .. base + 2) of rows base - 1 .. base + 2.
LUXEL_FUNC float postRowAt(vec4 row, int i) {
    return i == 0 ? row.x : (i == 1 ? row.y : (i == 2 ? row.z : row.w));
}
LUXEL_FUNC vec4 postRowOf(vec4 r0, vec4 r1, vec4 r2, vec4 r3, int j) {
    return j == 0 ? r0 : (j == 1 ? r1 : (j == 2 ? r2 : r3));
}
LUXEL_FUNC vec2 postGradientAt(vec4 r0, vec4 r1, vec4 r2, vec4 r3, int i, int j) {
    const vec4 row = postRowOf(r0, r1, r2, r3, j);
    const float gx = 0.5f * (postRowAt(row, i + 1) - postRowAt(row, i - 1));
    const float gy = 0.5f * (postRowAt(postRowOf(r0, r1, r2, r3, j + 1), i) -
                             postRowAt(postRowOf(r0, r1, r2, r3, j - 1), i));
    return vec2(gx, gy);
}

// Edge analysis at fractional position f (in [0, 1)^2 from texel (1, 1) of the grid): the
// gradient bilinearly blended from the four inner texels, its strength relative to the inner
// texels' luma range (1 for a clean step, so the measure does not depend on exposure).
LUXEL_FUNC PostEdge postEdgeSetup(vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec2 f) {
    const vec2 g = postGradientAt(r0, r1, r2, r3, 1, 1) * ((1.0f - f.x) * (1.0f - f.y)) +
                   postGradientAt(r0, r1, r2, r3, 2, 1) * (f.x * (1.0f - f.y)) +
                   postGradientAt(r0, r1, r2, r3, 1, 2) * ((1.0f - f.x) * f.y) +
                   postGradientAt(r0, r1, r2, r3, 2, 2) * (f.x * f.y);
    const float lo = min(min(r1.y, r1.z), min(r2.y, r2.z));
    const float hi = max(max(r1.y, r1.z), max(r2.y, r2.z));
    const float len = sqrt(g.x * g.x + g.y * g.y);
    const float scale = hi - lo + 1e-4f * max(hi, 0.0f) + 1e-12f;
    const float strength = clamp(2.0f * len / scale, 0.0f, 1.0f);
    const float edge = strength * strength;
    const vec2 n = len > 1e-20f ? g * (1.0f / len) : vec2(1.0f, 0.0f);
    return PostEdge(n, edge, 0.4f + 0.3f * edge);
}

// Weight of a texel at offset d (texel centre minus sample position, in source texels).
LUXEL_FUNC float postEdgeWeight(PostEdge e, vec2 d) {
    const float across = d.x * e.normal.x + d.y * e.normal.y;
    const float along = d.y * e.normal.x - d.x * e.normal.y;
    const float stretch = 1.0f / (1.0f + e.edge);
    const float r2 = across * across + (along * stretch) * (along * stretch);
    return postEdgeWindow(r2, e.lobe);
}

// Contrast-limited sharpening in the spirit of FSR 1 RCAS: c pushed away from the mean of its four
// neighbours by `sharpness`, then clamped to the five texels' range, so it never rings.
LUXEL_FUNC vec3 postSharpen(vec3 c, vec3 n, vec3 s, vec3 e, vec3 w, float sharpness) {
    const vec3 mean = (n + s + e + w) * 0.25f;
    const vec3 lo = min(min(min(n, s), min(e, w)), c);
    const vec3 hi = max(max(max(n, s), max(e, w)), c);
    const vec3 pushed = c + (c - mean) * sharpness;
    return min(max(pushed, lo), hi);
}

LUXEL_SHARED_END

#endif
