// Voxel renderer structures shared by C++ and GLSL (offsets checked below and, against the
// compiled shaders, in tests/gpu/shared_layout_test.cpp). Every field is a 4-byte scalar, so std430
// adds no padding.
//
// Buffers of voxel_render (set 0):
//   0 VoxelRenderParams
//   1 voxels: one uint per voxel (r | g << 8 | b << 16 | a << 24), chunk-major exactly like
//     VoxelWorld: chunk ((cz * chunksY + cy) * chunksX + cx) << 3 * chunkShift, then
//     (lz * chunk + ly) * chunk + lx inside it
//   2 solid voxels per chunk (uint), same chunk order
//   3 VoxelTextureInfo per texture slot
//   4 texels: vec4, per slot: the texture (linear RGB, linear alpha, rows top to bottom), then
//     its colour mip chain (premultiplied alpha), then its normal chain if it has a normal map
//     (TextureSet::colourMips / normalMips; levels and offsets: shared/texture_filter.h)
//   5 float[256]: srgbToLinear(i / 255), the CPU's own values
//   6 output: vec4 per pixel (linear RGB, 1), rows top to bottom
//   7 brick occupancy masks: uvec2 per 4^3 brick (low, high 32 bits of VoxelWorld::brickMask),
//     bricks ((bz * bricksY + by) * bricksX + bx)
//   8 brick reach (VoxelWorld::brickReach): 8 planes of one byte per brick, octant after octant,
//     each in the masks' brick order, packed four to a uint (byte i of the planes is bits
//     8 * (i & 3) of word i >> 2); VoxelWorld::brickReachData as it is
//   9 VoxelMaterial[LUXEL_VOXEL_MATERIALS]: the material of texture slot i (0..253), then the
//     plain blocks' material (physical lighting)
//   10 unused (the parameters are bound again; keeps the shadow bindings where
//      sun_visibility.glsl expects them)
//   11-14 sun visibility (shared/shadow_layout.h): ShadowParams, moments, distance field, light
//      levels; one-word placeholders unless LUXEL_VOXEL_SUN_VISIBILITY is set
//   15-17 light from emissive voxels (shared/emitter_light.h): the grid's offsets and lists and
//      the faces; one-word placeholders unless LUXEL_VOXEL_EMITTER_LIGHT is set
//
// voxel_cast (a batch of rays; the CPU twin is castRays in dda.h) binds 0-2 as above, then
// 3 VoxelCastRay per ray, 4 VoxelCastHit per ray, 5 brick masks, 6 brick reach.
#ifndef LUXEL_GPU_SHARED_VOXEL_LAYOUT_H
#define LUXEL_GPU_SHARED_VOXEL_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace luxel::gpu::shared {
using uint = std::uint32_t;
#endif

#define LUXEL_VOXEL_GROUP_X 8
#define LUXEL_VOXEL_GROUP_Y 8
#define LUXEL_VOXEL_BUFFERS 18
#define LUXEL_VOXEL_CAST_GROUP 64

// VoxelRenderParams.flags
#define LUXEL_VOXEL_FACE_SHADING 1u
#define LUXEL_VOXEL_SHADOWS 2u
#define LUXEL_VOXEL_PROCEDURAL_TEXTURE 4u
#define LUXEL_VOXEL_ENERGY_CONSERVING 8u
// The brick reach is current (VoxelWorld::emptySpaceCurrent); else chunk and brick jumps.
#define LUXEL_VOXEL_REACH_CURRENT 16u
// Physical lighting (ShadeOptions::Lighting::Physical), refraction on, exact Fresnel (else
// Schlick).
#define LUXEL_VOXEL_PHYSICAL 256u
#define LUXEL_VOXEL_REFRACTION 512u
#define LUXEL_VOXEL_FRESNEL_EXACT 1024u
// Physical: bend the shading normal by the slots' normal maps (ShadeOptions::normalMaps).
#define LUXEL_VOXEL_NORMAL_MAPS 2048u
// Physical with shadows: the sun's visibility comes from the shadow bindings 11-14
// (sun_visibility.glsl); else one hard shadow ray that sees cutouts, as the CPU's Hard method.
#define LUXEL_VOXEL_SUN_VISIBILITY 4096u
// Physical: light from emissive voxels onto other faces, from the lists at 15..17
// (shared/emitter_light.h); else those are one-word placeholders.
#define LUXEL_VOXEL_EMITTER_LIGHT 8192u

// Material table entries: 254 texture slots and the plain blocks' material (the last).
#define LUXEL_VOXEL_MATERIALS 255
#define LUXEL_VOXEL_PLAIN_MATERIAL 254
// VoxelMaterial.flags: the procedural texture applies; the slot has a material of its own.
#define LUXEL_VOXEL_MATERIAL_PROCEDURAL 1u
#define LUXEL_VOXEL_MATERIAL_OWN 2u
// Pending rays of the physical tracer's stack (reflection and refraction budget at most 16).
#define LUXEL_VOXEL_PATH_STACK 20
#define LUXEL_VOXEL_MAX_DEPTH 16

// Must equal kMaxCutoutContinuations (surface_cast.h).
#define LUXEL_VOXEL_MAX_CUTOUTS 64

struct VoxelRenderParams {
    // World.
    uint sizeX, sizeY, sizeZ;
    uint chunkShift;
    uint chunksX, chunksY, chunksZ;
    uint stepCap;  // resolved: never 0
    // Image and options.
    uint width, height;
    uint textureCount;
    uint flags;
    // Camera (Camera::rayAt in float).
    float positionX, positionY, positionZ;
    float tanHalf;
    float forwardX, forwardY, forwardZ;
    float aspect;
    float rightX, rightY, rightZ;
    uint maxReflections;
    float upX, upY, upZ;
    float ambient;
    // Sun, sky and materials.
    float sunX, sunY, sunZ;
    float reflectivity;
    float skyTopR, skyTopG, skyTopB;
    float textureStrength;
    float skyHorizonR, skyHorizonG, skyHorizonB;
    uint textureTexels;
    // Bricks (4^3 voxels) per axis.
    uint bricksX, bricksY, bricksZ;
    // Physical lighting.
    uint specular;  // LUXEL_VOXEL_SPECULAR_* (shared/voxel_shading.h)
    float sunIrradianceR, sunIrradianceG, sunIrradianceB;
    float skyAmbient;
    float alphaMin;  // smallest GGX alpha: the sun's image in a mirror
    // Anti-aliasing and texture filtering (render_image.h, texture_set.h).
    uint samplesPerPixel;  // 1..LUXEL_MAX_SAMPLES_PER_PIXEL
    uint textureFilter;    // LUXEL_TEXTURE_NEAREST, _TRILINEAR or _ANISOTROPIC
    uint maxAnisotropy;
    float coneSpread;  // primary cone spread per sample: pixel angle / sqrt(samplesPerPixel)
    // Light from emissive voxels (LUXEL_VOXEL_EMITTER_LIGHT, shared/emitter_light.h).
    uint emitterRays;    // shadow rays per face, 1..LUXEL_EMITTER_MAX_RAYS
    float emitterFloor;  // EmitterLights::floor()
    // The sky's model (LUXEL_SKY_GRADIENT: skyTop and skyHorizon; LUXEL_SKY_PREETHAM: the Perez
    // coefficients A..E of Y, x and y in turn and their zenith values over F(0, θs), as
    // shared/sky_preetham.h's PreethamSky).
    uint skyModel;
    float skyPerez[15];
    float skyZenithOverF0[3];
    // Physical: sky ambient rays per shaded point (ShadeOptions::skyAmbientRays, 0: the constant
    // share skyAmbient; shared/sky_ambient.h).
    uint skyAmbientRays;
};

// Push constants: the band of rows one dispatch renders (images are split into bands so no
// single dispatch runs long).
struct VoxelBandPush {
    uint rowOffset;
    uint rows;
};

// voxel_cast: one ray in, one hit out (dda.h's Ray and Hit in float).
struct VoxelCastRay {
    float originX, originY, originZ;
    float tMax;
    float directionX, directionY, directionZ;
    uint jumps;  // 0: visit every voxel (ChunkSkip::Disabled)
};

struct VoxelCastHit {
    uint flags;  // 1: hit, 2: capped
    int steps;
    int voxelX, voxelY, voxelZ;
    int normalX, normalY, normalZ;
    float t;
    float pointX, pointY, pointZ;
    float u, v;
    uint entry;  // octree casts: the hit leaf's entry (octree.h), for its colour; else 0
    uint pad0;
};

struct VoxelCastPush {
    uint rays;
    uint stepCap;  // resolved: never 0
};

// Output of voxel_render: linear RGB and 1, per pixel.
struct VoxelPixel {
    float r, g, b, a;
};

// A material (luxel/voxel/material.h) as the shader reads it.
struct VoxelMaterial {
    float albedoR, albedoG, albedoB;
    float metallic;
    float roughness, ior, transmission;
    uint flags;  // LUXEL_VOXEL_MATERIAL_*
    float absorptionR, absorptionG, absorptionB;
    float pad0;
    float emissionR, emissionG, emissionB;
    float pad1;
};

struct VoxelTextureInfo {
    uint texelOffset;  // first texel of the slot in the texel buffer
    uint width;
    uint height;
    float reflectivity;  // < 0: none (the renderer's default applies)
    uint mipOffset;      // first texel of the colour mip chain
    uint levels;         // mip levels (textureLevelCount)
    uint normalOffset;   // first texel of the normal chain (same levels)
    uint hasNormalMap;   // 0: flat
};

#ifdef __cplusplus
static_assert(sizeof(VoxelRenderParams) == 300);
static_assert(offsetof(VoxelRenderParams, skyAmbientRays) == 296);
static_assert(offsetof(VoxelRenderParams, skyModel) == 220);
static_assert(offsetof(VoxelRenderParams, skyPerez) == 224);
static_assert(offsetof(VoxelRenderParams, skyZenithOverF0) == 284);
static_assert(offsetof(VoxelRenderParams, specular) == 172);
static_assert(offsetof(VoxelRenderParams, alphaMin) == 192);
static_assert(offsetof(VoxelRenderParams, samplesPerPixel) == 196);
static_assert(offsetof(VoxelRenderParams, coneSpread) == 208);
static_assert(offsetof(VoxelRenderParams, emitterRays) == 212);
static_assert(offsetof(VoxelRenderParams, emitterFloor) == 216);
static_assert(sizeof(VoxelMaterial) == 64);
static_assert(offsetof(VoxelMaterial, absorptionR) == 32);
static_assert(offsetof(VoxelMaterial, emissionR) == 48);
static_assert(sizeof(VoxelCastRay) == 32);
static_assert(sizeof(VoxelCastHit) == 64);
static_assert(offsetof(VoxelRenderParams, width) == 32);
static_assert(offsetof(VoxelRenderParams, positionX) == 48);
static_assert(offsetof(VoxelRenderParams, maxReflections) == 92);
static_assert(offsetof(VoxelRenderParams, sunX) == 112);
static_assert(offsetof(VoxelRenderParams, textureTexels) == 156);
static_assert(sizeof(VoxelBandPush) == 8);
static_assert(offsetof(VoxelBandPush, rows) == 4);
static_assert(sizeof(VoxelTextureInfo) == 32);
static_assert(offsetof(VoxelTextureInfo, reflectivity) == 12);
static_assert(offsetof(VoxelTextureInfo, mipOffset) == 16);
static_assert(offsetof(VoxelTextureInfo, hasNormalMap) == 28);
}  // namespace luxel::gpu::shared
#endif

#endif
