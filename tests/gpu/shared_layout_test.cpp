// Shared C++/GLSL structs against what glslc actually emitted: the member offsets (SPIR-V
// OpMemberDecorate ... Offset) and array strides in the embedded shaders, compared with the C++
// offsetof and sizeof of the same struct. A member whose std430 offset differs from C++ (a vec3,
// a double, a reordered block) fails here, naming the shader, the binding and the member.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "gpu/layout_check.h"
#include "gpu/shaders/shared/cascade_picture_layout.h"
#include "gpu/shaders/shared/hrc_layout.h"
#include "gpu/shaders/shared/medium_layout.h"
#include "gpu/shaders/shared/near_emitters.h"
#include "gpu/shaders/shared/octree_layout.h"
#include "gpu/shaders/shared/rc_layout.h"
#include "gpu/shaders/shared/shadow_layout.h"
#include "gpu/shaders/shared/voxel_layout.h"
#include "gpu/spirv_reflect.h"

namespace luxel::gpu {
namespace {

using namespace layout_check;
using namespace shared;

TEST(GpuSharedLayout, ComparisonReportsEveryDifference) {
    // The checker itself: a shader layout that differs from C++ in one offset, in the member
    // count and in the stride must be reported, and an identical one must not.
    const CppLayout cpp{12, {0, 4, 8}};
    EXPECT_TRUE(compareLayouts({{0, 4, 8}, 12}, cpp, true).empty());
    EXPECT_EQ(compareLayouts({{0, 4, 16}, 12}, cpp, true).size(), 1u);  // a vec3-style shift
    EXPECT_EQ(compareLayouts({{0, 4, 8}, 16}, cpp, true).size(), 1u);   // padded element
    EXPECT_EQ(compareLayouts({{0, 4}, 12}, cpp, true).size(), 1u);      // a member missing
}

TEST(GpuSharedLayout, ReaderRejectsMalformedWords) {
    EXPECT_FALSE(reflectSpirv(std::vector<std::uint32_t>{1, 2, 3}).ok());
    // A valid header followed by an instruction claiming more words than there are.
    const std::vector<std::uint32_t> truncated{0x07230203, 0x10600, 0, 10, 0, (9u << 16) | 71u, 1};
    EXPECT_FALSE(reflectSpirv(truncated).ok());
}

TEST(GpuSharedLayout, WorkgroupSizesComeFromTheSharedConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    EXPECT_EQ(reflect("hrc_merge").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_HRC_GROUP_SIZE, 1, 1}));
    EXPECT_EQ(reflect("rc_cascade").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_RC_GROUP_SIZE, 1, 1}));
    EXPECT_EQ(reflect("voxel_render").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_VOXEL_GROUP_X, LUXEL_VOXEL_GROUP_Y, 1}));
    EXPECT_EQ(reflect("voxel_cast").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_VOXEL_CAST_GROUP, 1, 1}));
    EXPECT_EQ(reflect("octree_cast").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_OCTREE_CAST_GROUP, 1, 1}));
    EXPECT_EQ(reflect("octree_render").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_OCTREE_RENDER_GROUP_X,
                                            LUXEL_OCTREE_RENDER_GROUP_Y, 1}));
    EXPECT_EQ(reflect("octree_light_cache").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_OCTREE_LIGHT_CACHE_GROUP, 1, 1}));
}

TEST(GpuSharedLayout, OctreeRenderParams) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    using P = OctreeRenderParams;
    for (const char* shader : {"octree_render", "octree_light_cache"}) {
        expectBuffer(shader, 0,
                     {sizeof(P), {LUXEL_MEMBER(P, originX),       LUXEL_MEMBER(P, originY),
                                  LUXEL_MEMBER(P, originZ),       LUXEL_MEMBER(P, sunRadius),
                                  LUXEL_MEMBER(P, forwardX),      LUXEL_MEMBER(P, forwardY),
                                  LUXEL_MEMBER(P, forwardZ),      LUXEL_MEMBER(P, opacityScale),
                                  LUXEL_MEMBER(P, rightX),        LUXEL_MEMBER(P, rightY),
                                  LUXEL_MEMBER(P, rightZ),        LUXEL_MEMBER(P, albedo),
                                  LUXEL_MEMBER(P, upX),           LUXEL_MEMBER(P, upY),
                                  LUXEL_MEMBER(P, upZ),           LUXEL_MEMBER(P, phaseG),
                                  LUXEL_MEMBER(P, sunX),          LUXEL_MEMBER(P, sunY),
                                  LUXEL_MEMBER(P, sunZ),          LUXEL_MEMBER(P, ambient),
                                  LUXEL_MEMBER(P, sunR),          LUXEL_MEMBER(P, sunG),
                                  LUXEL_MEMBER(P, sunB),          LUXEL_MEMBER(P, octaveWeight),
                                  LUXEL_MEMBER(P, skyR),          LUXEL_MEMBER(P, skyG),
                                  LUXEL_MEMBER(P, skyB),          LUXEL_MEMBER(P, lightStride),
                                  LUXEL_MEMBER(P, width),         LUXEL_MEMBER(P, height),
                                  LUXEL_MEMBER(P, depth),         LUXEL_MEMBER(P, mode),
                                  LUXEL_MEMBER(P, sizeX),         LUXEL_MEMBER(P, sizeY),
                                  LUXEL_MEMBER(P, sizeZ),         LUXEL_MEMBER(P, threshold),
                                  LUXEL_MEMBER(P, shadowSamples), LUXEL_MEMBER(P, flags),
                                  LUXEL_MEMBER(P, octaves),       LUXEL_MEMBER(P, stepCap),
                                  LUXEL_MEMBER(P, windowLow),     LUXEL_MEMBER(P, windowHigh),
                                  LUXEL_MEMBER(P, pad0),          LUXEL_MEMBER(P, pad1)}},
                     /* element= */ false);
    }
    expectBuffer("octree_render", 3,
                 {sizeof(VoxelPixel),
                  {LUXEL_MEMBER(VoxelPixel, r), LUXEL_MEMBER(VoxelPixel, g),
                   LUXEL_MEMBER(VoxelPixel, b), LUXEL_MEMBER(VoxelPixel, a)}});
}

TEST(GpuSharedLayout, OctreeCastBuffersAndPushConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    using P = OctreeCastPush;
    expectPushConstants(
        "octree_cast", {sizeof(P),
                        {LUXEL_MEMBER(P, rays), LUXEL_MEMBER(P, stepCap), LUXEL_MEMBER(P, depth),
                         LUXEL_MEMBER(P, threshold), LUXEL_MEMBER(P, sizeX), LUXEL_MEMBER(P, sizeY),
                         LUXEL_MEMBER(P, sizeZ), LUXEL_MEMBER(P, flags)}});
    using R = VoxelCastRay;
    expectBuffer("octree_cast", 1,
                 {sizeof(R),
                  {LUXEL_MEMBER(R, originX), LUXEL_MEMBER(R, originY), LUXEL_MEMBER(R, originZ),
                   LUXEL_MEMBER(R, tMax), LUXEL_MEMBER(R, directionX), LUXEL_MEMBER(R, directionY),
                   LUXEL_MEMBER(R, directionZ), LUXEL_MEMBER(R, jumps)}});
    using H = VoxelCastHit;
    expectBuffer(
        "octree_cast", 2,
        {sizeof(H),
         {LUXEL_MEMBER(H, flags), LUXEL_MEMBER(H, steps), LUXEL_MEMBER(H, voxelX),
          LUXEL_MEMBER(H, voxelY), LUXEL_MEMBER(H, voxelZ), LUXEL_MEMBER(H, normalX),
          LUXEL_MEMBER(H, normalY), LUXEL_MEMBER(H, normalZ), LUXEL_MEMBER(H, t),
          LUXEL_MEMBER(H, pointX), LUXEL_MEMBER(H, pointY), LUXEL_MEMBER(H, pointZ),
          LUXEL_MEMBER(H, u), LUXEL_MEMBER(H, v), LUXEL_MEMBER(H, entry), LUXEL_MEMBER(H, pad0)}});
}

TEST(GpuSharedLayout, HrcPushConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    expectPushConstants(
        "hrc_extend",
        {sizeof(HrcExtendParams),
         {LUXEL_MEMBER(HrcExtendParams, level), LUXEL_MEMBER(HrcExtendParams, rows),
          LUXEL_MEMBER(HrcExtendParams, planesBelow), LUXEL_MEMBER(HrcExtendParams, planes)}});
    expectPushConstants(
        "hrc_trace",
        {sizeof(HrcTraceParams),
         {LUXEL_MEMBER(HrcTraceParams, level), LUXEL_MEMBER(HrcTraceParams, rows),
          LUXEL_MEMBER(HrcTraceParams, planes), LUXEL_MEMBER(HrcTraceParams, frameLength),
          LUXEL_MEMBER(HrcTraceParams, frustum), LUXEL_MEMBER(HrcTraceParams, canvasWidth),
          LUXEL_MEMBER(HrcTraceParams, canvasHeight), LUXEL_MEMBER(HrcTraceParams, transposed),
          LUXEL_MEMBER(HrcTraceParams, depthScale)}});
    expectPushConstants(
        "hrc_merge",
        {sizeof(HrcMergeParams),
         {LUXEL_MEMBER(HrcMergeParams, level), LUXEL_MEMBER(HrcMergeParams, rows),
          LUXEL_MEMBER(HrcMergeParams, planes), LUXEL_MEMBER(HrcMergeParams, upperPlanes),
          LUXEL_MEMBER(HrcMergeParams, hasUpper), LUXEL_MEMBER(HrcMergeParams, skyR),
          LUXEL_MEMBER(HrcMergeParams, skyG), LUXEL_MEMBER(HrcMergeParams, skyB),
          LUXEL_MEMBER(HrcMergeParams, frustum), LUXEL_MEMBER(HrcMergeParams, canvasWidth),
          LUXEL_MEMBER(HrcMergeParams, canvasHeight), LUXEL_MEMBER(HrcMergeParams, nearLights)}});
    expectPushConstants(
        "hrc_readout",
        {sizeof(HrcReadoutParams),
         {LUXEL_MEMBER(HrcReadoutParams, frustum), LUXEL_MEMBER(HrcReadoutParams, frameLength),
          LUXEL_MEMBER(HrcReadoutParams, rows), LUXEL_MEMBER(HrcReadoutParams, canvasWidth),
          LUXEL_MEMBER(HrcReadoutParams, canvasHeight), LUXEL_MEMBER(HrcReadoutParams, skyR),
          LUXEL_MEMBER(HrcReadoutParams, skyG), LUXEL_MEMBER(HrcReadoutParams, skyB)}});
    expectPushConstants(
        "hrc_finish",
        {sizeof(HrcFinishParams),
         {LUXEL_MEMBER(HrcFinishParams, width), LUXEL_MEMBER(HrcFinishParams, height),
          LUXEL_MEMBER(HrcFinishParams, frustums), LUXEL_MEMBER(HrcFinishParams, blur)}});
    expectPushConstants(
        "hrc_near_field",
        {sizeof(HrcNearFieldParams),
         {LUXEL_MEMBER(HrcNearFieldParams, width), LUXEL_MEMBER(HrcNearFieldParams, height),
          LUXEL_MEMBER(HrcNearFieldParams, count), LUXEL_MEMBER(HrcNearFieldParams, rays),
          LUXEL_MEMBER(HrcNearFieldParams, cutoff), LUXEL_MEMBER(HrcNearFieldParams, skyR),
          LUXEL_MEMBER(HrcNearFieldParams, skyG), LUXEL_MEMBER(HrcNearFieldParams, skyB),
          LUXEL_MEMBER(HrcNearFieldParams, reach)}});
}

TEST(GpuSharedLayout, RcPushConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    using P = RcCascadeParams;
    expectPushConstants(
        "rc_cascade",
        {sizeof(P), {LUXEL_MEMBER(P, width),        LUXEL_MEMBER(P, height),
                     LUXEL_MEMBER(P, probesX),      LUXEL_MEMBER(P, probesY),
                     LUXEL_MEMBER(P, rays),         LUXEL_MEMBER(P, stored),
                     LUXEL_MEMBER(P, upperProbesX), LUXEL_MEMBER(P, upperProbesY),
                     LUXEL_MEMBER(P, upperStored),  LUXEL_MEMBER(P, hasUpper),
                     LUXEL_MEMBER(P, bilinearFix),  LUXEL_MEMBER(P, spacing),
                     LUXEL_MEMBER(P, upperSpacing), LUXEL_MEMBER(P, intervalStart),
                     LUXEL_MEMBER(P, intervalEnd),  LUXEL_MEMBER(P, upperIntervalStart),
                     LUXEL_MEMBER(P, skyR),         LUXEL_MEMBER(P, skyG),
                     LUXEL_MEMBER(P, skyB),         LUXEL_MEMBER(P, offsetX),
                     LUXEL_MEMBER(P, offsetY),      LUXEL_MEMBER(P, upperOffsetX),
                     LUXEL_MEMBER(P, upperOffsetY), LUXEL_MEMBER(P, pad0)}});
}

// The radiance cascades' picture: its push constants, the faces' table and the picture (the
// light buffer's RgbTexel and bindings 0..14 are checked with their own shaders).
TEST(GpuSharedLayout, CascadesPicturePushConstantsAndFaceSlots) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    using P = CascadePicturePush;
    expectPushConstants("cascades_picture", {sizeof(P),
                                             {LUXEL_MEMBER(P, seedLow),
                                              LUXEL_MEMBER(P, seedHigh),
                                              LUXEL_MEMBER(P, sunRays),
                                              LUXEL_MEMBER(P, specularRays),
                                              LUXEL_MEMBER(P, materialFlags),
                                              LUXEL_MEMBER(P, faces),
                                              LUXEL_MEMBER(P, slotMask),
                                              LUXEL_MEMBER(P, sunX),
                                              LUXEL_MEMBER(P, sunY),
                                              LUXEL_MEMBER(P, sunZ),
                                              LUXEL_MEMBER(P, sunIrradianceR),
                                              LUXEL_MEMBER(P, sunIrradianceG),
                                              LUXEL_MEMBER(P, sunIrradianceB),
                                              LUXEL_MEMBER(P, sunOneMinusCos),
                                              LUXEL_MEMBER(P, sunRadianceScale),
                                              LUXEL_MEMBER(P, sunOverPdfScale),
                                              LUXEL_MEMBER(P, sunTangentX),
                                              LUXEL_MEMBER(P, sunTangentY),
                                              LUXEL_MEMBER(P, sunTangentZ),
                                              LUXEL_MEMBER(P, sunBitangentX),
                                              LUXEL_MEMBER(P, sunBitangentY),
                                              LUXEL_MEMBER(P, sunBitangentZ),
                                              LUXEL_MEMBER(P, refineCount),
                                              LUXEL_MEMBER(P, refineSamples),
                                              LUXEL_MEMBER(P, lampCellsX),
                                              LUXEL_MEMBER(P, lampCellsY),
                                              LUXEL_MEMBER(P, lampCellsZ)}});
    using S = CascadeFaceSlot;
    expectBuffer("cascades_picture", 16,
                 {sizeof(S),
                  {LUXEL_MEMBER(S, keyLow), LUXEL_MEMBER(S, keyHigh), LUXEL_MEMBER(S, id),
                   LUXEL_MEMBER(S, pad0)}});
    for (int binding : {15, 19}) {
        expectBuffer(
            "cascades_picture", binding,
            {sizeof(RgbTexel),
             {LUXEL_MEMBER(RgbTexel, r), LUXEL_MEMBER(RgbTexel, g), LUXEL_MEMBER(RgbTexel, b)}});
    }
    using E = CascadeNearEmitter;
    expectBuffer(
        "cascades_picture", 21,
        {sizeof(E),
         {LUXEL_MEMBER(E, x), LUXEL_MEMBER(E, y), LUXEL_MEMBER(E, z), LUXEL_MEMBER(E, normal),
          LUXEL_MEMBER(E, r), LUXEL_MEMBER(E, g), LUXEL_MEMBER(E, b), LUXEL_MEMBER(E, extent)}});
    // The glossy surfaces' lamps (shared/glossy_emitters.h) and the ray caster's emitters
    // (shared/emitter_light.h) are the same struct.
    expectBuffer(
        "cascades_picture", 24,
        {sizeof(E),
         {LUXEL_MEMBER(E, x), LUXEL_MEMBER(E, y), LUXEL_MEMBER(E, z), LUXEL_MEMBER(E, normal),
          LUXEL_MEMBER(E, r), LUXEL_MEMBER(E, g), LUXEL_MEMBER(E, b), LUXEL_MEMBER(E, extent)}});
    expectBuffer(
        "voxel_render", 17,
        {sizeof(E),
         {LUXEL_MEMBER(E, x), LUXEL_MEMBER(E, y), LUXEL_MEMBER(E, z), LUXEL_MEMBER(E, normal),
          LUXEL_MEMBER(E, r), LUXEL_MEMBER(E, g), LUXEL_MEMBER(E, b), LUXEL_MEMBER(E, extent)}});
}

TEST(GpuSharedLayout, VoxelBuffersAndPushConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    using P = VoxelRenderParams;
    const CppLayout params{sizeof(P),
                           {LUXEL_MEMBER(P, sizeX),
                            LUXEL_MEMBER(P, sizeY),
                            LUXEL_MEMBER(P, sizeZ),
                            LUXEL_MEMBER(P, chunkShift),
                            LUXEL_MEMBER(P, chunksX),
                            LUXEL_MEMBER(P, chunksY),
                            LUXEL_MEMBER(P, chunksZ),
                            LUXEL_MEMBER(P, stepCap),
                            LUXEL_MEMBER(P, width),
                            LUXEL_MEMBER(P, height),
                            LUXEL_MEMBER(P, textureCount),
                            LUXEL_MEMBER(P, flags),
                            LUXEL_MEMBER(P, positionX),
                            LUXEL_MEMBER(P, positionY),
                            LUXEL_MEMBER(P, positionZ),
                            LUXEL_MEMBER(P, tanHalf),
                            LUXEL_MEMBER(P, forwardX),
                            LUXEL_MEMBER(P, forwardY),
                            LUXEL_MEMBER(P, forwardZ),
                            LUXEL_MEMBER(P, aspect),
                            LUXEL_MEMBER(P, rightX),
                            LUXEL_MEMBER(P, rightY),
                            LUXEL_MEMBER(P, rightZ),
                            LUXEL_MEMBER(P, maxReflections),
                            LUXEL_MEMBER(P, upX),
                            LUXEL_MEMBER(P, upY),
                            LUXEL_MEMBER(P, upZ),
                            LUXEL_MEMBER(P, ambient),
                            LUXEL_MEMBER(P, sunX),
                            LUXEL_MEMBER(P, sunY),
                            LUXEL_MEMBER(P, sunZ),
                            LUXEL_MEMBER(P, reflectivity),
                            LUXEL_MEMBER(P, skyTopR),
                            LUXEL_MEMBER(P, skyTopG),
                            LUXEL_MEMBER(P, skyTopB),
                            LUXEL_MEMBER(P, textureStrength),
                            LUXEL_MEMBER(P, skyHorizonR),
                            LUXEL_MEMBER(P, skyHorizonG),
                            LUXEL_MEMBER(P, skyHorizonB),
                            LUXEL_MEMBER(P, textureTexels),
                            LUXEL_MEMBER(P, bricksX),
                            LUXEL_MEMBER(P, bricksY),
                            LUXEL_MEMBER(P, bricksZ),
                            LUXEL_MEMBER(P, specular),
                            LUXEL_MEMBER(P, sunIrradianceR),
                            LUXEL_MEMBER(P, sunIrradianceG),
                            LUXEL_MEMBER(P, sunIrradianceB),
                            LUXEL_MEMBER(P, skyAmbient),
                            LUXEL_MEMBER(P, alphaMin),
                            LUXEL_MEMBER(P, samplesPerPixel),
                            LUXEL_MEMBER(P, textureFilter),
                            LUXEL_MEMBER(P, maxAnisotropy),
                            LUXEL_MEMBER(P, coneSpread),
                            LUXEL_MEMBER(P, emitterRays),
                            LUXEL_MEMBER(P, emitterFloor),
                            LUXEL_MEMBER(P, skyModel),
                            LUXEL_MEMBER(P, skyPerez),
                            LUXEL_MEMBER(P, skyZenithOverF0),
                            LUXEL_MEMBER(P, skyAmbientRays)}};
    for (const char* shader : {"voxel_render", "voxel_cast", "path_trace"}) {
        expectBuffer(shader, 0, params, /* element= */ false);
    }
    expectBuffer(
        "voxel_render", 3,
        {sizeof(VoxelTextureInfo),
         {LUXEL_MEMBER(VoxelTextureInfo, texelOffset), LUXEL_MEMBER(VoxelTextureInfo, width),
          LUXEL_MEMBER(VoxelTextureInfo, height), LUXEL_MEMBER(VoxelTextureInfo, reflectivity),
          LUXEL_MEMBER(VoxelTextureInfo, mipOffset), LUXEL_MEMBER(VoxelTextureInfo, levels),
          LUXEL_MEMBER(VoxelTextureInfo, normalOffset),
          LUXEL_MEMBER(VoxelTextureInfo, hasNormalMap)}});
    // The sun visibility parameters where sun_visibility.glsl puts them in the render pass.
    static_assert(LUXEL_VOXEL_BUFFERS == 18);
    using S = ShadowParams;
    expectBuffer("voxel_render", 11,
                 {sizeof(S), {LUXEL_MEMBER(S, lightX),       LUXEL_MEMBER(S, lightY),
                              LUXEL_MEMBER(S, lightZ),       LUXEL_MEMBER(S, tanRadius),
                              LUXEL_MEMBER(S, uX),           LUXEL_MEMBER(S, uY),
                              LUXEL_MEMBER(S, uZ),           LUXEL_MEMBER(S, uMin),
                              LUXEL_MEMBER(S, vX),           LUXEL_MEMBER(S, vY),
                              LUXEL_MEMBER(S, vZ),           LUXEL_MEMBER(S, vMin),
                              LUXEL_MEMBER(S, texel),        LUXEL_MEMBER(S, depthTop),
                              LUXEL_MEMBER(S, depthRange),   LUXEL_MEMBER(S, depthBias),
                              LUXEL_MEMBER(S, momentBias),   LUXEL_MEMBER(S, lightBleed),
                              LUXEL_MEMBER(S, normalOffset), LUXEL_MEMBER(S, blendNear),
                              LUXEL_MEMBER(S, blendFar),     LUXEL_MEMBER(S, sdfNormalOffset),
                              LUXEL_MEMBER(S, pad1),         LUXEL_MEMBER(S, pad2),
                              LUXEL_MEMBER(S, sizeX),        LUXEL_MEMBER(S, sizeY),
                              LUXEL_MEMBER(S, sizeZ),        LUXEL_MEMBER(S, mapSize),
                              LUXEL_MEMBER(S, method),       LUXEL_MEMBER(S, flags),
                              LUXEL_MEMBER(S, sdfMaxSteps),  LUXEL_MEMBER(S, pad3)}},
                 /* element= */ false);
    expectPushConstants("voxel_render", {sizeof(VoxelBandPush),
                                         {LUXEL_MEMBER(VoxelBandPush, rowOffset),
                                          LUXEL_MEMBER(VoxelBandPush, rows)}});
    using R = VoxelCastRay;
    expectBuffer("voxel_cast", 3,
                 {sizeof(R),
                  {LUXEL_MEMBER(R, originX), LUXEL_MEMBER(R, originY), LUXEL_MEMBER(R, originZ),
                   LUXEL_MEMBER(R, tMax), LUXEL_MEMBER(R, directionX), LUXEL_MEMBER(R, directionY),
                   LUXEL_MEMBER(R, directionZ), LUXEL_MEMBER(R, jumps)}});
    using H = VoxelCastHit;
    expectBuffer(
        "voxel_cast", 4,
        {sizeof(H),
         {LUXEL_MEMBER(H, flags), LUXEL_MEMBER(H, steps), LUXEL_MEMBER(H, voxelX),
          LUXEL_MEMBER(H, voxelY), LUXEL_MEMBER(H, voxelZ), LUXEL_MEMBER(H, normalX),
          LUXEL_MEMBER(H, normalY), LUXEL_MEMBER(H, normalZ), LUXEL_MEMBER(H, t),
          LUXEL_MEMBER(H, pointX), LUXEL_MEMBER(H, pointY), LUXEL_MEMBER(H, pointZ),
          LUXEL_MEMBER(H, u), LUXEL_MEMBER(H, v), LUXEL_MEMBER(H, entry), LUXEL_MEMBER(H, pad0)}});
    expectPushConstants(
        "voxel_cast", {sizeof(VoxelCastPush),
                       {LUXEL_MEMBER(VoxelCastPush, rays), LUXEL_MEMBER(VoxelCastPush, stepCap)}});
}

// The element structs of the buffers that used to be bare float/uint arrays: the 2D medium, the
// RGB buffers (accumulators, cascades, fluence), the HRC table entries and cone words, the voxel
// output.
TEST(GpuSharedLayout, BufferElementStructs) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    const CppLayout medium{
        sizeof(MediumTexel),
        {LUXEL_MEMBER(MediumTexel, sigmaR), LUXEL_MEMBER(MediumTexel, sigmaG),
         LUXEL_MEMBER(MediumTexel, sigmaB), LUXEL_MEMBER(MediumTexel, emissionR),
         LUXEL_MEMBER(MediumTexel, emissionG), LUXEL_MEMBER(MediumTexel, emissionB)}};
    for (const char* shader : {"hrc_trace", "hrc_finish", "rc_cascade"}) {
        expectBuffer(shader, 0, medium);
    }
    const CppLayout rgb{
        sizeof(RgbTexel),
        {LUXEL_MEMBER(RgbTexel, r), LUXEL_MEMBER(RgbTexel, g), LUXEL_MEMBER(RgbTexel, b)}};
    for (const auto& [shader, binding] :
         {std::pair{"hrc_readout", 1u}, std::pair{"hrc_finish", 1u}, std::pair{"hrc_finish", 2u},
          std::pair{"rc_cascade", 1u}, std::pair{"rc_cascade", 2u}}) {
        expectBuffer(shader, binding, rgb);
    }
    const CppLayout cones{sizeof(HrcConePair), {LUXEL_MEMBER(HrcConePair, evenOddRows)}};
    for (const auto& [shader, binding] :
         {std::pair{"hrc_merge", 1u}, std::pair{"hrc_merge", 2u}, std::pair{"hrc_readout", 0u}}) {
        expectBuffer(shader, binding, cones);
    }
    const CppLayout entry{sizeof(HrcTableEntry),
                          {LUXEL_MEMBER(HrcTableEntry, radianceRG),
                           LUXEL_MEMBER(HrcTableEntry, radianceBTransmittanceR),
                           LUXEL_MEMBER(HrcTableEntry, transmittanceGB)}};
    for (const auto& [shader, binding] :
         {std::pair{"hrc_trace", 1u}, std::pair{"hrc_extend", 0u}, std::pair{"hrc_extend", 1u},
          std::pair{"hrc_merge", 0u}}) {
        expectBuffer(shader, binding, entry);
    }
    using M = VoxelMaterial;
    expectBuffer("voxel_render", 9,
                 {sizeof(M),
                  {LUXEL_MEMBER(M, albedoR), LUXEL_MEMBER(M, albedoG), LUXEL_MEMBER(M, albedoB),
                   LUXEL_MEMBER(M, metallic), LUXEL_MEMBER(M, roughness), LUXEL_MEMBER(M, ior),
                   LUXEL_MEMBER(M, transmission), LUXEL_MEMBER(M, flags),
                   LUXEL_MEMBER(M, absorptionR), LUXEL_MEMBER(M, absorptionG),
                   LUXEL_MEMBER(M, absorptionB), LUXEL_MEMBER(M, pad0), LUXEL_MEMBER(M, emissionR),
                   LUXEL_MEMBER(M, emissionG), LUXEL_MEMBER(M, emissionB), LUXEL_MEMBER(M, pad1)}});
    expectBuffer("voxel_render", 6,
                 {sizeof(VoxelPixel),
                  {LUXEL_MEMBER(VoxelPixel, r), LUXEL_MEMBER(VoxelPixel, g),
                   LUXEL_MEMBER(VoxelPixel, b), LUXEL_MEMBER(VoxelPixel, a)}});
}

}  // namespace
}  // namespace luxel::gpu
