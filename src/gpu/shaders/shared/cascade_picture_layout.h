// The voxel radiance cascades' picture on the GPU (docs/algorithms/voxel-radiance-cascades.md
// §4.3; CPU reference: RadianceCascades::render in src/voxel/cascades/cascade_picture.cpp),
// shared by C++ (src/voxel/cascades/cascade_picture_gpu.cpp) and GLSL
// (voxel/cascades_picture.comp.glsl); offsets checked below and, against the compiled shader, in
// tests/gpu/shared_layout_test.cpp. Every field is a 4-byte scalar, so std430 adds no padding.
//
// Buffers of cascades_picture (set 0): 0..14 are voxel_render's (shared/voxel_layout.h: the
// world, textures, materials and VoxelRenderParams with the camera and the sky), then
//   15 the faces' light (RgbTexel, the sections of shared/voxel_cascades_layout.h), written by
//      the lighting passes and read here where they left it
//   16 CascadeFaceSlot: the faces' open-addressing table, (voxel, normal) -> face id
//   17 float: the GGX lobe's directional albedo table (src/voxel/ggx_albedo.h)
//   18 float: the picture, RGB per pixel, rows top to bottom
//   19..21 the emitters near each face (shared/near_emitters.h)
//   22 uint: the adaptive pass (src/voxel/cascades/adaptive_samples.h), used when refineCount
//      > 0: the RGB (float bits) of each pixel it draws again, 3 x refineCount words written by
//      the pass, then the pixels (y * width + x) to draw, refineCount words
//   23..24 the lamps the glossy surfaces light-sample (shared/glossy_emitters.h)
#ifndef LUXEL_GPU_SHARED_CASCADE_PICTURE_LAYOUT_H
#define LUXEL_GPU_SHARED_CASCADE_PICTURE_LAYOUT_H

#include "glsl_compat.h"

LUXEL_SHARED_BEGIN

#define LUXEL_PICTURE_GROUP_X 8
#define LUXEL_PICTURE_GROUP_Y 8
#define LUXEL_PICTURE_BUFFERS 25
// Glass and polished metal followed one inside another (kSolverFollowDepth, solver_surface.h):
// the shader unrolls the CPU's recursion into this many levels.
#define LUXEL_PICTURE_FOLLOW_DEPTH 2
// Exits into the air whose refracted light a medium's walk takes before it drops the light
// reflected back inside (kPictureCameraAirExits, kPictureFollowedAirExits: cascade_picture.h):
// at the camera's surface, and at a glass face followed from it.
#define LUXEL_PICTURE_CAMERA_AIR_EXITS 2
#define LUXEL_PICTURE_FOLLOWED_AIR_EXITS 1
// Metals at most this rough are followed (kSolverFollowRoughness).
#define LUXEL_PICTURE_FOLLOW_ROUGHNESS 0.1
// A GGX lobe at most this sharp (alpha; roughness 0.05) takes one reflection direction
// (kSolverSharpAlpha, solver_surface.h).
#define LUXEL_PICTURE_SHARP_ALPHA 0.0025
// A GGX lobe at least this rough (alpha; roughness 0.67) takes one reflection direction too,
// counted unbiased (kSolverRoughAlpha, solver_surface.h).
#define LUXEL_PICTURE_ROUGH_ALPHA 0.45
// The GGX albedo table's nodes per side (cosView, alpha; ggx_albedo.cpp).
#define LUXEL_PICTURE_ALBEDO_SIDE 24
#define LUXEL_PICTURE_EMPTY_SLOT 0xFFFFFFFFu

// CascadePicturePush::flags.
#define LUXEL_PICTURE_REFRACTION 1u     // ShadeOptions::refraction
#define LUXEL_PICTURE_FRESNEL_EXACT 2u  // ShadeOptions::fresnel
#define LUXEL_PICTURE_TRANSMISSION 4u   // some material transmits (sun rays walk media)

struct CascadePicturePush {
    uint seedLow, seedHigh;  // the picture's GGX directions (PathRng's seed)
    uint sunRays;            // shadow rays over the sun's disk at the camera's faces
    uint specularRays;       // GGX directions at the camera's faces
    uint materialFlags;      // LUXEL_PICTURE_*; read as PathTracePush::materialFlags
    uint faces;              // faces in the light buffer (its section length)
    uint slotMask;           // the face table's slots - 1 (a power of two)
    float sunX, sunY, sunZ;  // unit, towards the sun
    float sunIrradianceR, sunIrradianceG, sunIrradianceB;
    // The sun's disk (SunDisk, in double and rounded): 1 - cos r (0: a delta sun), its radiance
    // per irradiance 1 / (pi sin^2 r), radiance / pdf per irradiance 2 / (1 + cos r) (1 for a
    // delta sun) and the tangents its spiral turns about.
    float sunOneMinusCos, sunRadianceScale, sunOverPdfScale;
    float sunTangentX, sunTangentY, sunTangentZ;
    float sunBitangentX, sunBitangentY, sunBitangentZ;
    // The adaptive pass: 0 draws every pixel with VoxelRenderParams::samplesPerPixel rays; n > 0
    // draws the n pixels of binding 22 (invocation y * width + x takes entry y * width + x) with
    // refineSamples rays each.
    uint refineCount, refineSamples;
    // The lamps' grid (shared/glossy_emitters.h): its cells per axis; 0: no lamps to sample.
    uint lampCellsX, lampCellsY, lampCellsZ;
};

// One slot of the faces' table: the key of (voxel, normal) and the face's id (EMPTY: free).
struct CascadeFaceSlot {
    uint keyLow;   // x | y << 12 | normal << 24 (sides below 4096, normalIndex 0..5)
    uint keyHigh;  // z
    uint id;
    uint pad0;
};

LUXEL_FUNC uint cascadeFaceKeyLow(int x, int y, int normal) {
    return uint(x) | (uint(y) << 12u) | (uint(normal) << 24u);
}

// The slot a key's probe starts at (a 32-bit mix of both words; linear probing from there).
LUXEL_FUNC uint cascadeFaceHash(uint keyLow, uint keyHigh) {
    uint h = keyLow * 0x9E3779B1u ^ (keyHigh + 0x7F4A7C15u) * 0x85EBCA77u;
    h ^= h >> 15u;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12u;
    return h;
}

LUXEL_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(luxel::gpu::shared::CascadePicturePush) == 108);
static_assert(offsetof(luxel::gpu::shared::CascadePicturePush, sunX) == 28);
static_assert(offsetof(luxel::gpu::shared::CascadePicturePush, sunOneMinusCos) == 52);
static_assert(offsetof(luxel::gpu::shared::CascadePicturePush, sunBitangentZ) == 84);
static_assert(offsetof(luxel::gpu::shared::CascadePicturePush, refineSamples) == 92);
static_assert(offsetof(luxel::gpu::shared::CascadePicturePush, lampCellsZ) == 104);
static_assert(sizeof(luxel::gpu::shared::CascadeFaceSlot) == 16);
#endif

#endif
