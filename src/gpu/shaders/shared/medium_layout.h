// The 2D medium as the GPU passes read it (HRC trace and finish, RC cascade): one MediumTexel per
// pixel, rows top to bottom, packed on the CPU by packMediumForGpu (src/gi2d/medium_gpu.h).
// Six 4-byte scalars, so std430 puts them at the offsets C++ does (checked by the layout test,
// which reads the offsets glslc emitted).
#ifndef LUXEL_GPU_SHARED_MEDIUM_LAYOUT_H
#define LUXEL_GPU_SHARED_MEDIUM_LAYOUT_H

#include "glsl_compat.h"

LUXEL_SHARED_BEGIN

struct MediumTexel {
    float sigmaR, sigmaG, sigmaB;           // absorption coefficient per pixel length
    float emissionR, emissionG, emissionB;  // emitted radiance per pixel length
};

// One RGB value of the 2D passes' float buffers (HRC accumulators, RC cascades, the fluence):
// three floats, 12 bytes, no padding in std430.
struct RgbTexel {
    float r, g, b;
};

// The medium's column-major copy made on the GPU from its rows (medium_transpose.comp.glsl).
struct MediumTransposeParams {
    uint width, height;
    uint pad0, pad1;
};

LUXEL_FUNC vec3 mediumSigma(MediumTexel m) {
    return vec3(m.sigmaR, m.sigmaG, m.sigmaB);
}
LUXEL_FUNC vec3 mediumEmission(MediumTexel m) {
    return vec3(m.emissionR, m.emissionG, m.emissionB);
}
LUXEL_FUNC vec3 texelRgb(RgbTexel t) {
    return vec3(t.r, t.g, t.b);
}
LUXEL_FUNC RgbTexel rgbTexel(vec3 v) {
    return RgbTexel(v.x, v.y, v.z);
}

LUXEL_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(luxel::gpu::shared::MediumTexel) == 24);
static_assert(offsetof(luxel::gpu::shared::MediumTexel, emissionR) == 12);
static_assert(sizeof(luxel::gpu::shared::RgbTexel) == 12);
static_assert(sizeof(luxel::gpu::shared::MediumTransposeParams) == 16);
#endif

#endif
