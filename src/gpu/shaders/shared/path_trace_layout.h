// The GPU voxel path tracer's structures, shared by C++ (src/voxel/path_trace_gpu.cpp) and GLSL
// (voxel/path_trace.comp.glsl); offsets checked below and, against the compiled shader, in
// tests/gpu/shared_layout_test.cpp. Every field is a 4-byte scalar, so std430 adds no padding.
//
// Buffers of path_trace (set 0): 0..14 are voxel_render's (shared/voxel_layout.h: the world,
// textures, materials and VoxelRenderParams with the camera and the sky), then
//   15 PathEmitterVoxel per emissive voxel (PathEmitters; one placeholder when there are none)
//   16 PathPixelSums per pixel of the image, rows top to bottom: the samples of the dispatches
//      since the last download (the first writes, the others add)
#ifndef LUXEL_GPU_SHARED_PATH_TRACE_LAYOUT_H
#define LUXEL_GPU_SHARED_PATH_TRACE_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace luxel::gpu::shared {
using uint = std::uint32_t;
#endif

#define LUXEL_PATH_GROUP_X 8
#define LUXEL_PATH_GROUP_Y 8
#define LUXEL_PATH_BUFFERS 17
// PathTracePush::materialFlags (the path tracer reads them whatever the ray caster's lighting).
#define LUXEL_PATH_REFRACTION 1u
#define LUXEL_PATH_FRESNEL_EXACT 2u
#define LUXEL_PATH_SUN_CHAINS 4u  // sun light sampling passes delta surfaces (sunThroughGlass)

// Push constants: the rows and the samples one dispatch traces, and the path options.
struct PathTracePush {
    uint rowOffset, rows;       // the band of rows
    uint firstSample, samples;  // samples firstSample .. firstSample + samples - 1 of each pixel
    uint seedLow, seedHigh;     // PathTraceOptions::seed
    uint maxBounces;            // PathTraceOptions::maxBounces
    uint rouletteAfter;         // PathTraceOptions::rouletteAfter
    uint emitters;              // emissive voxels sampled as lights (0: none)
    float sunX, sunY, sunZ;     // unit, towards the sun
    float sunIrradianceR, sunIrradianceG, sunIrradianceB;
    uint accumulate;  // 0: write the pixels' sums; 1: add to those there (same shift)
    // The sun's disk (SunDisk, computed in double and rounded): 1 - cos r (0: a delta sun), the
    // density of its cone 1 / (2 pi (1 - cos r)), its radiance per irradiance 1 / (pi sin^2 r)
    // and the tangents of the axis its samples turn about.
    float sunOneMinusCos, sunPdf, sunRadianceScale;
    float sunTangentX, sunTangentY, sunTangentZ;
    float sunBitangentX, sunBitangentY, sunBitangentZ;
    uint materialFlags;  // LUXEL_PATH_* above: ShadeOptions::refraction, ::fresnel, sun chains
    uint pad0, pad1;
};

struct PathEmitterVoxel {
    int x, y, z;
    int pad0;
};

// Samples of a pixel, shifted by its first sample s0 so that a pixel whose samples
// are all equal sums to exactly 0 (float sums of raw values would leave a false variance):
// shift = s0, sum = sum (s - s0), sumSquares = sum (s - s0)^2, for RGB and Rec. 709 luminance.
struct PathPixelSums {
    float shiftR, shiftG, shiftB, shiftL;
    float sumR, sumG, sumB, sumL;
    float squaresR, squaresG, squaresB, squaresL;
};

#ifdef __cplusplus
static_assert(sizeof(PathTracePush) == 112);
static_assert(offsetof(PathTracePush, sunOneMinusCos) == 64);
static_assert(offsetof(PathTracePush, sunBitangentZ) == 96);
static_assert(offsetof(PathTracePush, seedLow) == 16);
static_assert(offsetof(PathTracePush, emitters) == 32);
static_assert(offsetof(PathTracePush, sunIrradianceR) == 48);
static_assert(sizeof(PathEmitterVoxel) == 16);
static_assert(sizeof(PathPixelSums) == 48);
static_assert(offsetof(PathPixelSums, sumR) == 16);
static_assert(offsetof(PathPixelSums, squaresR) == 32);
}  // namespace luxel::gpu::shared
#endif

#endif
