// Vanilla RC structures shared by C++ and GLSL (offsets checked below and, against the compiled
// shader, in tests/gpu/shared_layout_test.cpp).
//
// Cascade buffers hold pre-averaged float RGB: probe-major, `stored` values per probe,
// index ((py * probesX + px) * stored + s) * 3. Medium buffer: six floats per canvas pixel
// (sigma rgb, emission rgb).
#ifndef LUXEL_GPU_SHARED_RC_LAYOUT_H
#define LUXEL_GPU_SHARED_RC_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace luxel::gpu::shared {
using uint = std::uint32_t;
#endif

#define LUXEL_RC_GROUP_SIZE 64

// Push constants of rc_cascade: merges cascade i (all its probes) from cascade i + 1.
struct RcCascadeParams {
    uint width;
    uint height;
    uint probesX;
    uint probesY;
    uint rays;    // directions of this cascade
    uint stored;  // values stored per probe (this cascade)
    uint upperProbesX;
    uint upperProbesY;
    uint upperStored;
    uint hasUpper;  // 0 at the top cascade
    uint bilinearFix;
    float spacing;
    float upperSpacing;
    float intervalStart;
    float intervalEnd;
    float upperIntervalStart;
    float skyR, skyG, skyB;
    // Probe grid offsets of this cascade and the one above (RcCascade::offsetX/Y; probe jitter).
    float offsetX, offsetY;
    float upperOffsetX, upperOffsetY;
    uint pad0;
};

#ifdef __cplusplus
static_assert(sizeof(RcCascadeParams) == 96);
static_assert(offsetof(RcCascadeParams, offsetX) == 76);
static_assert(offsetof(RcCascadeParams, spacing) == 44);
static_assert(offsetof(RcCascadeParams, skyR) == 64);
}  // namespace luxel::gpu::shared
#endif

#endif
