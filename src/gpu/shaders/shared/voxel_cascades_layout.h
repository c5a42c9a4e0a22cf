// The voxel radiance cascades' lighting pass on the GPU (docs/algorithms/voxel-radiance-cascades.md
// §4; CPU reference: lightingPass in src/voxel/cascades/cascade_light.cpp). Push constants of
// its four dispatches and the codes of the segments, shared by C++ and GLSL (offsets checked
// below). Buffers are flat arrays with one section per level, addressed by the offsets here:
// codes (uint; the passages through glass first), corners (8 probe indices then 8 weights per
// probe or face), radiance and child means (RgbTexel), sky means (RgbTexel), solid angles
// (float), the faces' light (RgbTexel, six sections of `faces` entries: albedo, emitted, direct
// sun, emitter irradiance, irradiance, outgoing), the faces' (normal, first code) pairs, and
// each normal's (bin, weight bits) pairs.
#ifndef LUXEL_GPU_SHARED_VOXEL_CASCADES_LAYOUT_H
#define LUXEL_GPU_SHARED_VOXEL_CASCADES_LAYOUT_H

#include "glsl_compat.h"

LUXEL_SHARED_BEGIN

#define LUXEL_CASCADES_GROUP_SIZE 64
#define LUXEL_CASCADE_CONTINUE 0xFFFFFFFFu
#define LUXEL_CASCADE_SKY 0xFFFFFFFEu
#define LUXEL_CASCADE_VOID 0xFFFFFFFCu
// Codes from here up to VOID pass glass or water: PASSAGE + the index of a passage of
// PASSAGE_WORDS words (face entered, next code, transmittance r, g, b as float bits) at the start
// of the codes buffer; at most MAX_PASSAGES in a chain (src/voxel/cascades/cascade_passages.h).
#define LUXEL_CASCADE_PASSAGE 0x80000000u
#define LUXEL_CASCADE_PASSAGE_WORDS 5u
#define LUXEL_CASCADE_MAX_PASSAGES 16u

// The faces' light sections, in order.
#define LUXEL_FACE_ALBEDO 0u
#define LUXEL_FACE_EMITTED 1u
#define LUXEL_FACE_DIRECT 2u
#define LUXEL_FACE_EMITTER 3u
#define LUXEL_FACE_IRRADIANCE 4u
#define LUXEL_FACE_OUTGOING 5u

struct CascadeOutgoingParams {
    uint faces;
    uint pad0, pad1, pad2;
};

// Merges one level (all its probes and bins) from the child means of the level above.
struct CascadeMergeParams {
    uint probes;
    uint bins;
    uint top;  // 1: one code per bin, no corners
    uint faces;
    uint codeOffset;
    uint cornerOffset;     // in probes
    uint radianceOffset;   // this level's radiance
    uint upperMeanOffset;  // the level above's child means
    uint skyOffset;
    uint pad0, pad1, pad2;
};

// The solid-angle mean of each bin's four children, for the level below.
struct CascadeChildMeanParams {
    uint probes;
    uint binSide;  // this level's bins per side
    uint radianceOffset;
    uint meanOffset;
    uint solidAngleOffset;
    uint pad0, pad1, pad2;
};

// Each face's irradiance from its own segments and level 0.
struct CascadeGatherParams {
    uint faces;
    uint levelBins;  // level 0's bins
    uint cornerOffset;
    uint skyOffset;  // the faces' bins' sky means
    uint normalFirst[6];
    uint normalCount[6];
};

LUXEL_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(luxel::gpu::shared::CascadeOutgoingParams) == 16);
static_assert(sizeof(luxel::gpu::shared::CascadeMergeParams) == 48);
static_assert(offsetof(luxel::gpu::shared::CascadeMergeParams, skyOffset) == 32);
static_assert(sizeof(luxel::gpu::shared::CascadeChildMeanParams) == 32);
static_assert(sizeof(luxel::gpu::shared::CascadeGatherParams) == 64);
static_assert(offsetof(luxel::gpu::shared::CascadeGatherParams, normalCount) == 40);
#endif

#endif
