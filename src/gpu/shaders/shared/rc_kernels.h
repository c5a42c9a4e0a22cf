// Per-probe arithmetic of vanilla radiance cascades both backends run
// (docs/algorithms/radiance-cascades-2d.md §1, §2): probe positions, ray directions, the bilinear
// footprint on the cascade above, and the pre-averaging groups. Compiled as C++ in double by the
// CPU cascade pass (src/gi2d/rc/rc_cascade_pass.h) and as GLSL in float by rc_cascade.
//
// The includer defines LUXEL_REAL / LUXEL_REAL2 (double/dvec2 in C++, float/vec2 in GLSL).
#ifndef LUXEL_GPU_SHARED_RC_KERNELS_H
#define LUXEL_GPU_SHARED_RC_KERNELS_H

#include "glsl_compat.h"

#define LUXEL_RC_TWO_PI 6.28318530717958648

LUXEL_SHARED_BEGIN

// Centre of probe (px, py) on a grid with probes every `spacing` pixels.
LUXEL_FUNC LUXEL_REAL2 rcProbeCentre(int px, int py, LUXEL_REAL spacing) {
    return LUXEL_REAL2((LUXEL_REAL(px) + LUXEL_REAL(0.5)) * spacing,
                       (LUXEL_REAL(py) + LUXEL_REAL(0.5)) * spacing);
}

// Direction k of `rays` evenly spaced directions, at the centres of their angular bins.
LUXEL_FUNC LUXEL_REAL2 rcDirection(int k, int rays) {
    const LUXEL_REAL angle =
        (LUXEL_REAL(k) + LUXEL_REAL(0.5)) * (LUXEL_REAL(LUXEL_RC_TWO_PI) / LUXEL_REAL(rays));
    return LUXEL_REAL2(cos(angle), sin(angle));
}

// Directions averaged into one stored value (pre-averaging: cascade 0 stores 1 mean, higher
// cascades the mean of each group of 4 children).
LUXEL_FUNC int rcGroup(int rays, int stored) {
    return rays / stored;
}

// The 2 x 2 probes of a grid around point p, clamped to the grid, and their bilinear weights.
struct RcBilinear {
    int x0, x1, y0, y1;
    float wx0, wx1, wy0, wy1;
};

LUXEL_FUNC RcBilinear rcBilinearAt(LUXEL_REAL2 p, LUXEL_REAL spacing, int probesX, int probesY) {
    const LUXEL_REAL u = p.x / spacing - LUXEL_REAL(0.5);
    const LUXEL_REAL v = p.y / spacing - LUXEL_REAL(0.5);
    const LUXEL_REAL fu = floor(u);
    const LUXEL_REAL fv = floor(v);
    const float tx = float(u - fu);
    const float ty = float(v - fv);
    const int ix = int(fu);
    const int iy = int(fv);
    return RcBilinear(clamp(ix, 0, probesX - 1), clamp(ix + 1, 0, probesX - 1),
                      clamp(iy, 0, probesY - 1), clamp(iy + 1, 0, probesY - 1), 1.0f - tx, tx,
                      1.0f - ty, ty);
}

LUXEL_FUNC int rcBilinearX(RcBilinear b, int a) {
    return a == 0 ? b.x0 : b.x1;
}
LUXEL_FUNC int rcBilinearY(RcBilinear b, int a) {
    return a == 0 ? b.y0 : b.y1;
}
LUXEL_FUNC float rcBilinearWeight(RcBilinear b, int a, int c) {
    return (a == 0 ? b.wx0 : b.wx1) * (c == 0 ? b.wy0 : b.wy1);
}

LUXEL_SHARED_END

#endif
