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

LUXEL_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(luxel::gpu::shared::MediumTexel) == 24);
static_assert(offsetof(luxel::gpu::shared::MediumTexel, emissionR) == 12);
#endif

#endif
