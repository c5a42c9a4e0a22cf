// Sun visibility structures shared by C++ and GLSL (sun_visibility.glsl and the batch pass
// shadow_visibility.comp.glsl; the CPU builds every array: SunVisibility in
// include/luxel/voxel/shadows/sun_visibility.h). Every field is a 4-byte scalar, so std430 adds no
// padding.
//
// Buffers (set 0; the render pass binds them at 11..14, the batch pass at 0..3):
//   params   ShadowParams
//   moments  uint per word: fp32 moments 4 words per texel (float bits), 16-bit optimized moments
//            2 words per texel (q0 | q1 << 16, q2 | q3 << 16); texels row by row, mapSize a side
//   field    float per voxel: the signed distance field (DistanceField::values), x fastest, then
//            as many words of feature offsets (DistanceField::features, soft_shadow.h's
//            packSdfFeature: normal floats in [1, 2) read by floatBitsToUint)
//   levels   uint per 4 voxels: flood-fill light levels, voxel i in byte (i & 3) of word i >> 2
// An array a method does not use holds one dummy word.
//
// The batch pass adds 4 ShadowQueryGpu per query and 5 float V per query, push ShadowBatchPush.
#ifndef LUXEL_GPU_SHARED_SHADOW_LAYOUT_H
#define LUXEL_GPU_SHARED_SHADOW_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace luxel::gpu::shared {
using uint = std::uint32_t;
#endif

// ShadowParams.method: the order of luxel::voxel::ShadowMethod.
#define LUXEL_SHADOW_HARD 0u
#define LUXEL_SHADOW_EXACT 1u
#define LUXEL_SHADOW_MSM 2u
#define LUXEL_SHADOW_VSM 3u
#define LUXEL_SHADOW_SDF 4u
#define LUXEL_SHADOW_BLEND 5u
#define LUXEL_SHADOW_FLOOD 6u

// ShadowParams.flags.
#define LUXEL_SHADOW_QUANTIZED 1u    // moments are 16-bit optimized
#define LUXEL_SHADOW_SDF_NEAR 2u     // the blend uses the SDF near the camera
#define LUXEL_SHADOW_MIN_IN_BAND 4u  // min(V_msm, V_sdf) inside the band
#define LUXEL_SHADOW_SDF_CUBES 8u    // the SDF estimator reads the exact cube distance

#define LUXEL_SHADOW_GROUP 64

struct ShadowParams {
    float lightX, lightY, lightZ, tanRadius;       // unit, towards the sun; tan(angular radius)
    float uX, uY, uZ, uMin;                        // map axis u and its lowest value
    float vX, vY, vZ, vMin;                        // map axis v
    float texel, depthTop, depthRange, depthBias;  // texel side; depth = (top - p.l) / range
    float momentBias, lightBleed, normalOffset, blendNear;
    float blendFar, sdfNormalOffset, pad1, pad2;
    int sizeX, sizeY, sizeZ, mapSize;  // world size (field, levels); map texels a side
    uint method, flags, sdfMaxSteps, pad3;
};

struct ShadowQueryGpu {
    float x, y, z, footprint;
    int normalX, normalY, normalZ, pad0;
};

struct ShadowBatchPush {
    uint count;
};

#ifdef __cplusplus
static_assert(sizeof(ShadowParams) == 128);
static_assert(offsetof(ShadowParams, sizeX) == 96);
static_assert(offsetof(ShadowParams, method) == 112);
static_assert(sizeof(ShadowQueryGpu) == 32);
}  // namespace luxel::gpu::shared
#endif

#endif
