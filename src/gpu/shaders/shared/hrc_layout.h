// HRC structures and constants shared by C++ and GLSL (one definition; offsets checked below and
// in tests/gpu/shared_layout_test.cpp).
//
// Ray table T_n in memory (binary16, rows innermost), one entry = 3 words:
//   word 0: L.r | L.g << 16    word 1: L.b | T.r << 16    word 2: T.g | T.b << 16
//   entry index = (p * (2^n + 1) + k) * rows + y
//
// Merged cones R_n in memory (binary16, channel planes, rows innermost): cone i of plane p holds
// three planes (r, g, b) of hrcConeRowHalves(rows) values, the rows padded to an even count, so
// that a 32-bit word holds rows y and y + 1 of one channel (y even in the low half):
//   half index = ((p * 2^n + i) * 3 + c) * hrcConeRowHalves(rows) + y   (hrc_kernels.h)
// hrc_merge writes whole words: each invocation merges two rows.
#ifndef LUXEL_GPU_SHARED_HRC_LAYOUT_H
#define LUXEL_GPU_SHARED_HRC_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace luxel::gpu::shared {
using uint = std::uint32_t;
#endif

// Rows per workgroup of the HRC passes.
#define LUXEL_HRC_GROUP_SIZE 64
// Directions per pixel of the exact near field (§12.3), one invocation each: hrc_near_field's
// workgroup size.
#define LUXEL_HRC_NEAR_FIELD_RAYS 128
// 32-bit words per ray-table entry (six binary16 values).
#define LUXEL_HRC_ENTRY_WORDS 3

// One ray-table entry (the layout above); LUXEL_HRC_ENTRY_WORDS words.
struct HrcTableEntry {
    uint radianceRG;               // L.r | L.g << 16 (binary16)
    uint radianceBTransmittanceR;  // L.b | T.r << 16
    uint transmittanceGB;          // T.g | T.b << 16
};

// One word of a merged-cone buffer (the cone layout above): one channel of two neighbouring rows.
struct HrcConePair {
    uint evenOddRows;  // row y | row y + 1 << 16 (binary16, y even)
};

// Push constants of hrc_extend: builds T_level from T_{level-1}.
struct HrcExtendParams {
    uint level;        // n >= 1
    uint rows;         // frame rows
    uint planesBelow;  // plane count of T_{n-1}
    uint planes;       // plane count of T_n
};

// Push constants of hrc_trace: marches T_level exactly through the canvas medium seen in the
// frustum's frame. Medium buffer: per canvas pixel six floats, sigma rgb then emission rgb, at
// y * canvasWidth + x, or at x * canvasHeight + y when `transposed`; frame pixel (u, v) reads
// canvas pixel hrcFrameToCanvas (hrc_kernels.h). The two layouts are uploaded once for all four
// frustums: the +-x frustums read the transposed one, so that neighbouring threads (neighbouring
// frame rows) read neighbouring memory in every frustum.
struct HrcTraceParams {
    uint level;
    uint rows;
    uint planes;
    uint frameLength;  // frame pixels along the axis
    uint frustum;      // 0 +x, 1 +y, 2 -x, 3 -y (FrustumFrame)
    uint canvasWidth;
    uint canvasHeight;
    uint transposed;   // 1: the buffer is column-major (x * canvasHeight + y)
    float depthScale;  // hrcTracedDepthScale (hrc_kernels.h)
};

// Push constants of hrc_merge: R_level from R_{level+1} (hasUpper = 0 at the top cascade).
// R buffers: binary16 channel planes, the cone layout above. Near-light mask (nearLights = 1, read
// at cascade 0 only): a byte per canvas pixel at y * canvasWidth + x, four to a 32-bit word (low
// byte first); frame pixel (u, v) reads canvas pixel hrcFrameToCanvas.
struct HrcMergeParams {
    uint level;
    uint rows;
    uint planes;
    uint upperPlanes;
    uint hasUpper;
    float skyR, skyG, skyB;  // boundary radiance
    uint frustum;            // 0 +x, 1 +y, 2 -x, 3 -y (FrustumFrame)
    uint canvasWidth;
    uint canvasHeight;
    uint nearLights;  // 1: weigh cascade 0's near-probe blend by the mask (hrcNearRowWeightAt)
};

// Push constants of hrc_readout: adds R_0 (the cone layout above) at the plane beyond each pixel
// into the canvas-space accumulator (three floats per canvas pixel).
struct HrcReadoutParams {
    uint frustum;  // 0 +x, 1 +y, 2 -x, 3 -y
    uint frameLength;
    uint rows;
    uint canvasWidth;
    uint canvasHeight;
    float skyR, skyG, skyB;
};

// Push constants of hrc_finish: cross blur (Eq 21), own half-pixel segment, 1 / (2 pi).
// Canvas medium buffer: six floats per pixel as above.
struct HrcFinishParams {
    uint width;
    uint height;
    uint frustums;  // how many frustums were summed
    uint blur;      // 1 = opacity-gated cross blur
};

// Push constants of hrc_near_field (§12.3's exact near field): `count` canvas pixels, listed as
// y * width + x, each overwritten in the fluence by the mean over `rays` (=
// LUXEL_HRC_NEAR_FIELD_RAYS) directions marched from its centre for at most `reach` px or until
// every channel's transmittance is below `cutoff` (the sky beyond the canvas).
struct HrcNearFieldParams {
    uint width;
    uint height;
    uint count;
    uint rays;
    float cutoff;
    float skyR, skyG, skyB;
    float reach;
};

#ifdef __cplusplus
static_assert(sizeof(HrcTableEntry) == LUXEL_HRC_ENTRY_WORDS * 4);
static_assert(sizeof(HrcConePair) == 4);
static_assert(sizeof(HrcTraceParams) == 36);
static_assert(offsetof(HrcTraceParams, frustum) == 16);
static_assert(sizeof(HrcMergeParams) == 48);
static_assert(offsetof(HrcMergeParams, nearLights) == 44);
static_assert(offsetof(HrcMergeParams, skyR) == 20);
static_assert(sizeof(HrcReadoutParams) == 32);
static_assert(offsetof(HrcReadoutParams, skyR) == 20);
static_assert(sizeof(HrcFinishParams) == 16);
static_assert(sizeof(HrcNearFieldParams) == 36);
static_assert(sizeof(HrcExtendParams) == 16);
static_assert(offsetof(HrcExtendParams, rows) == 4);
static_assert(offsetof(HrcExtendParams, planesBelow) == 8);
static_assert(offsetof(HrcExtendParams, planes) == 12);
}  // namespace luxel::gpu::shared
#endif

#endif
