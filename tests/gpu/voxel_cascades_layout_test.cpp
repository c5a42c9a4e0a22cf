// The voxel radiance cascades' push constants against what glslc emitted for their shaders
// (member offsets and block sizes), and the shaders' workgroup size.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "gpu/layout_check.h"
#include "gpu/shaders/shared/voxel_cascades_layout.h"

namespace luxel::gpu {
namespace {

using namespace layout_check;
using namespace shared;

TEST(GpuSharedLayout, VoxelCascadesPushConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    expectPushConstants(
        "cascades_outgoing",
        {sizeof(CascadeOutgoingParams),
         {LUXEL_MEMBER(CascadeOutgoingParams, faces), LUXEL_MEMBER(CascadeOutgoingParams, pad0),
          LUXEL_MEMBER(CascadeOutgoingParams, pad1), LUXEL_MEMBER(CascadeOutgoingParams, pad2)}});
    using M = CascadeMergeParams;
    expectPushConstants("cascades_merge",
                        {sizeof(M),
                         {LUXEL_MEMBER(M, probes), LUXEL_MEMBER(M, bins), LUXEL_MEMBER(M, top),
                          LUXEL_MEMBER(M, faces), LUXEL_MEMBER(M, codeOffset),
                          LUXEL_MEMBER(M, cornerOffset), LUXEL_MEMBER(M, radianceOffset),
                          LUXEL_MEMBER(M, upperMeanOffset), LUXEL_MEMBER(M, skyOffset),
                          LUXEL_MEMBER(M, pad0), LUXEL_MEMBER(M, pad1), LUXEL_MEMBER(M, pad2)}});
    using C = CascadeChildMeanParams;
    expectPushConstants(
        "cascades_child_mean",
        {sizeof(C),
         {LUXEL_MEMBER(C, probes), LUXEL_MEMBER(C, binSide), LUXEL_MEMBER(C, radianceOffset),
          LUXEL_MEMBER(C, meanOffset), LUXEL_MEMBER(C, solidAngleOffset), LUXEL_MEMBER(C, pad0),
          LUXEL_MEMBER(C, pad1), LUXEL_MEMBER(C, pad2)}});
    using G = CascadeGatherParams;
    expectPushConstants(
        "cascades_gather",
        {sizeof(G),
         {LUXEL_MEMBER(G, faces), LUXEL_MEMBER(G, levelBins), LUXEL_MEMBER(G, cornerOffset),
          LUXEL_MEMBER(G, skyOffset), LUXEL_MEMBER(G, normalFirst), LUXEL_MEMBER(G, normalCount)}});
    for (const char* shader :
         {"cascades_outgoing", "cascades_merge", "cascades_child_mean", "cascades_gather"}) {
        EXPECT_EQ(reflect(shader).workgroupSize,
                  (std::array<std::uint32_t, 3>{LUXEL_CASCADES_GROUP_SIZE, 1, 1}))
            << shader;
    }
}

}  // namespace
}  // namespace luxel::gpu
