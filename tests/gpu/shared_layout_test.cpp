// Shared C++/GLSL structs against what glslc actually emitted: the member offsets (SPIR-V
// OpMemberDecorate ... Offset) and array strides in the embedded shaders, compared with the C++
// offsetof and sizeof of the same struct. A member whose std430 offset differs from C++ (a vec3,
// a double, a reordered block) fails here, naming the shader, the binding and the member.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "gpu/embedded_shaders.h"
#include "gpu/shaders/shared/hrc_layout.h"
#include "gpu/shaders/shared/medium_layout.h"
#include "gpu/shaders/shared/rc_layout.h"
#include "gpu/shaders/shared/voxel_layout.h"
#include "gpu/spirv_reflect.h"

namespace luxel::gpu {
namespace {

// The C++ side of one struct: its size and the offsetof of every member, in declaration order.
struct CppLayout {
    std::size_t size = 0;
    std::vector<std::size_t> offsets;
};

#define LUXEL_MEMBER(S, m) offsetof(S, m)

// Mismatches between the shader's layout of a struct and the C++ one, one line each (empty when
// they agree). `element`: the struct is a runtime array's element, so its stride must be sizeof.
std::vector<std::string> compareLayouts(const SpirvStruct& shader, const CppLayout& cpp,
                                        bool element) {
    std::vector<std::string> problems;
    if (shader.offsets.size() != cpp.offsets.size()) {
        problems.push_back("the shader's struct has " + std::to_string(shader.offsets.size()) +
                           " members, C++ lists " + std::to_string(cpp.offsets.size()));
        return problems;
    }
    for (std::size_t m = 0; m < cpp.offsets.size(); ++m) {
        if (shader.offsets[m] != cpp.offsets[m]) {
            problems.push_back("member " + std::to_string(m) + " is at byte " +
                               std::to_string(shader.offsets[m]) + " in the shader, " +
                               std::to_string(cpp.offsets[m]) + " in C++");
        }
    }
    if (element && shader.arrayStride != cpp.size) {
        problems.push_back("array stride " + std::to_string(shader.arrayStride) +
                           " in the shader, sizeof " + std::to_string(cpp.size) + " in C++");
    }
    return problems;
}

SpirvReflection reflect(const std::string& shader) {
    const auto words = detail::embeddedShader(shader);
    EXPECT_FALSE(words.empty()) << "no embedded shader " << shader;
    auto reflection = reflectSpirv(words);
    EXPECT_TRUE(reflection.ok()) << shader << ": " << reflection.error().message();
    return reflection.ok() ? std::move(*reflection) : SpirvReflection{};
}

void expectPushConstants(const std::string& shader, const CppLayout& cpp) {
    const SpirvReflection r = reflect(shader);
    ASSERT_TRUE(r.hasPushConstants) << shader << " has no push-constant block";
    for (const std::string& p : compareLayouts(r.pushConstants, cpp, false)) {
        ADD_FAILURE() << shader << " push constants: " << p;
    }
}

void expectBuffer(const std::string& shader, std::uint32_t binding, const CppLayout& cpp,
                  bool element = true) {
    const SpirvReflection r = reflect(shader);
    auto s = r.bufferElement(binding);
    ASSERT_TRUE(s.ok()) << shader << ": " << s.error().message();
    for (const std::string& p : compareLayouts(*s, cpp, element)) {
        ADD_FAILURE() << shader << " binding " << binding << ": " << p;
    }
}

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
    EXPECT_EQ(reflect("hrc_merge").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_HRC_GROUP_SIZE, 1, 1}));
    EXPECT_EQ(reflect("rc_cascade").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_RC_GROUP_SIZE, 1, 1}));
    EXPECT_EQ(reflect("voxel_render").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_VOXEL_GROUP_X, LUXEL_VOXEL_GROUP_Y, 1}));
}

TEST(GpuSharedLayout, HrcPushConstants) {
    expectPushConstants(
        "hrc_extend",
        {sizeof(HrcExtendParams),
         {LUXEL_MEMBER(HrcExtendParams, level), LUXEL_MEMBER(HrcExtendParams, rows),
          LUXEL_MEMBER(HrcExtendParams, planesBelow), LUXEL_MEMBER(HrcExtendParams, planes)}});
    expectPushConstants(
        "hrc_trace",
        {sizeof(HrcTraceParams),
         {LUXEL_MEMBER(HrcTraceParams, level), LUXEL_MEMBER(HrcTraceParams, rows),
          LUXEL_MEMBER(HrcTraceParams, planes), LUXEL_MEMBER(HrcTraceParams, frameLength)}});
    expectPushConstants(
        "hrc_merge",
        {sizeof(HrcMergeParams),
         {LUXEL_MEMBER(HrcMergeParams, level), LUXEL_MEMBER(HrcMergeParams, rows),
          LUXEL_MEMBER(HrcMergeParams, planes), LUXEL_MEMBER(HrcMergeParams, upperPlanes),
          LUXEL_MEMBER(HrcMergeParams, hasUpper), LUXEL_MEMBER(HrcMergeParams, skyR),
          LUXEL_MEMBER(HrcMergeParams, skyG), LUXEL_MEMBER(HrcMergeParams, skyB)}});
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
}

TEST(GpuSharedLayout, RcPushConstants) {
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
                     LUXEL_MEMBER(P, skyB),         LUXEL_MEMBER(P, pad0)}});
}

TEST(GpuSharedLayout, VoxelBuffersAndPushConstants) {
    using P = VoxelRenderParams;
    expectBuffer("voxel_render", 0,
                 {sizeof(P), {LUXEL_MEMBER(P, sizeX),        LUXEL_MEMBER(P, sizeY),
                              LUXEL_MEMBER(P, sizeZ),        LUXEL_MEMBER(P, chunkShift),
                              LUXEL_MEMBER(P, chunksX),      LUXEL_MEMBER(P, chunksY),
                              LUXEL_MEMBER(P, chunksZ),      LUXEL_MEMBER(P, stepCap),
                              LUXEL_MEMBER(P, width),        LUXEL_MEMBER(P, height),
                              LUXEL_MEMBER(P, textureCount), LUXEL_MEMBER(P, flags),
                              LUXEL_MEMBER(P, positionX),    LUXEL_MEMBER(P, positionY),
                              LUXEL_MEMBER(P, positionZ),    LUXEL_MEMBER(P, tanHalf),
                              LUXEL_MEMBER(P, forwardX),     LUXEL_MEMBER(P, forwardY),
                              LUXEL_MEMBER(P, forwardZ),     LUXEL_MEMBER(P, aspect),
                              LUXEL_MEMBER(P, rightX),       LUXEL_MEMBER(P, rightY),
                              LUXEL_MEMBER(P, rightZ),       LUXEL_MEMBER(P, maxReflections),
                              LUXEL_MEMBER(P, upX),          LUXEL_MEMBER(P, upY),
                              LUXEL_MEMBER(P, upZ),          LUXEL_MEMBER(P, ambient),
                              LUXEL_MEMBER(P, sunX),         LUXEL_MEMBER(P, sunY),
                              LUXEL_MEMBER(P, sunZ),         LUXEL_MEMBER(P, reflectivity),
                              LUXEL_MEMBER(P, skyTopR),      LUXEL_MEMBER(P, skyTopG),
                              LUXEL_MEMBER(P, skyTopB),      LUXEL_MEMBER(P, textureStrength),
                              LUXEL_MEMBER(P, skyHorizonR),  LUXEL_MEMBER(P, skyHorizonG),
                              LUXEL_MEMBER(P, skyHorizonB),  LUXEL_MEMBER(P, textureTexels)}},
                 /* element= */ false);
    expectBuffer(
        "voxel_render", 3,
        {sizeof(VoxelTextureInfo),
         {LUXEL_MEMBER(VoxelTextureInfo, texelOffset), LUXEL_MEMBER(VoxelTextureInfo, width),
          LUXEL_MEMBER(VoxelTextureInfo, height), LUXEL_MEMBER(VoxelTextureInfo, reflectivity)}});
    expectPushConstants("voxel_render", {sizeof(VoxelBandPush),
                                         {LUXEL_MEMBER(VoxelBandPush, rowOffset),
                                          LUXEL_MEMBER(VoxelBandPush, rows)}});
}

}  // namespace
}  // namespace luxel::gpu
