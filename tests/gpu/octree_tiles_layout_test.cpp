// The tile passes' shared structs (shared/octree_tiles_layout.h) against the compiled
// octree_tiles shader: member offsets, the state array's stride, the push constants and the
// workgroup size.
#include <gtest/gtest.h>

#include <array>

#include "gpu/layout_check.h"
#include "gpu/shaders/shared/octree_tiles_layout.h"

namespace luxel::gpu {
namespace {

using namespace layout_check;
using namespace shared;

TEST(OctreeTilesLayout, WorkgroupSizeComesFromTheSharedConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    EXPECT_EQ(
        reflect("octree_tiles").workgroupSize,
        (std::array<std::uint32_t, 3>{LUXEL_OCTREE_TILES_GROUP_X, LUXEL_OCTREE_TILES_GROUP_Y, 1}));
}

TEST(OctreeTilesLayout, TileStateAndPushConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    using S = OctreeTileState;
    expectBuffer("octree_tiles", 3,
                 {sizeof(S),
                  {LUXEL_MEMBER(S, status), LUXEL_MEMBER(S, cellX), LUXEL_MEMBER(S, cellY),
                   LUXEL_MEMBER(S, cellZ), LUXEL_MEMBER(S, level), LUXEL_MEMBER(S, entry),
                   LUXEL_MEMBER(S, samples), LUXEL_MEMBER(S, pass)}});
    using P = OctreeTilesPush;
    expectPushConstants("octree_tiles", {sizeof(P),
                                         {LUXEL_MEMBER(P, pass), LUXEL_MEMBER(P, level),
                                          LUXEL_MEMBER(P, parentLevel), LUXEL_MEMBER(P, shade)}});
}

TEST(OctreeTilesLayout, ParamsAndPixelsAreThoseOfOctreeRender) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    using R = OctreeRenderParams;
    expectBuffer("octree_tiles", 0,
                 {sizeof(R), {LUXEL_MEMBER(R, originX),       LUXEL_MEMBER(R, originY),
                              LUXEL_MEMBER(R, originZ),       LUXEL_MEMBER(R, sunRadius),
                              LUXEL_MEMBER(R, forwardX),      LUXEL_MEMBER(R, forwardY),
                              LUXEL_MEMBER(R, forwardZ),      LUXEL_MEMBER(R, opacityScale),
                              LUXEL_MEMBER(R, rightX),        LUXEL_MEMBER(R, rightY),
                              LUXEL_MEMBER(R, rightZ),        LUXEL_MEMBER(R, albedo),
                              LUXEL_MEMBER(R, upX),           LUXEL_MEMBER(R, upY),
                              LUXEL_MEMBER(R, upZ),           LUXEL_MEMBER(R, phaseG),
                              LUXEL_MEMBER(R, sunX),          LUXEL_MEMBER(R, sunY),
                              LUXEL_MEMBER(R, sunZ),          LUXEL_MEMBER(R, ambient),
                              LUXEL_MEMBER(R, sunR),          LUXEL_MEMBER(R, sunG),
                              LUXEL_MEMBER(R, sunB),          LUXEL_MEMBER(R, octaveWeight),
                              LUXEL_MEMBER(R, skyR),          LUXEL_MEMBER(R, skyG),
                              LUXEL_MEMBER(R, skyB),          LUXEL_MEMBER(R, lightStride),
                              LUXEL_MEMBER(R, width),         LUXEL_MEMBER(R, height),
                              LUXEL_MEMBER(R, depth),         LUXEL_MEMBER(R, mode),
                              LUXEL_MEMBER(R, sizeX),         LUXEL_MEMBER(R, sizeY),
                              LUXEL_MEMBER(R, sizeZ),         LUXEL_MEMBER(R, threshold),
                              LUXEL_MEMBER(R, shadowSamples), LUXEL_MEMBER(R, flags),
                              LUXEL_MEMBER(R, octaves),       LUXEL_MEMBER(R, stepCap),
                              LUXEL_MEMBER(R, windowLow),     LUXEL_MEMBER(R, windowHigh),
                              LUXEL_MEMBER(R, pad0),          LUXEL_MEMBER(R, pad1)}},
                 false);
    using V = VoxelPixel;
    expectBuffer(
        "octree_tiles", 4,
        {sizeof(V),
         {LUXEL_MEMBER(V, r), LUXEL_MEMBER(V, g), LUXEL_MEMBER(V, b), LUXEL_MEMBER(V, a)}});
}

}  // namespace
}  // namespace luxel::gpu
