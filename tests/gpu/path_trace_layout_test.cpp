// The GPU path tracer's shared structs (src/gpu/shaders/shared/path_trace_layout.h) against the
// compiled path_trace shader: workgroup size, push constants, the emitter and sum buffers, and
// the ray caster's material table it reads at the same binding.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "gpu/layout_check.h"
#include "gpu/shaders/shared/path_trace_layout.h"
#include "gpu/shaders/shared/voxel_layout.h"

namespace luxel::gpu {
namespace {

using namespace layout_check;
using namespace shared;

TEST(GpuSharedLayout, PathTraceBuffersAndPushConstants) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    EXPECT_EQ(reflect("path_trace").workgroupSize,
              (std::array<std::uint32_t, 3>{LUXEL_PATH_GROUP_X, LUXEL_PATH_GROUP_Y, 1}));
    using P = PathTracePush;
    expectPushConstants("path_trace", {sizeof(P),
                                       {LUXEL_MEMBER(P, rowOffset),
                                        LUXEL_MEMBER(P, rows),
                                        LUXEL_MEMBER(P, firstSample),
                                        LUXEL_MEMBER(P, samples),
                                        LUXEL_MEMBER(P, seedLow),
                                        LUXEL_MEMBER(P, seedHigh),
                                        LUXEL_MEMBER(P, maxBounces),
                                        LUXEL_MEMBER(P, rouletteAfter),
                                        LUXEL_MEMBER(P, emitters),
                                        LUXEL_MEMBER(P, sunX),
                                        LUXEL_MEMBER(P, sunY),
                                        LUXEL_MEMBER(P, sunZ),
                                        LUXEL_MEMBER(P, sunIrradianceR),
                                        LUXEL_MEMBER(P, sunIrradianceG),
                                        LUXEL_MEMBER(P, sunIrradianceB),
                                        LUXEL_MEMBER(P, accumulate),
                                        LUXEL_MEMBER(P, sunOneMinusCos),
                                        LUXEL_MEMBER(P, sunPdf),
                                        LUXEL_MEMBER(P, sunRadianceScale),
                                        LUXEL_MEMBER(P, sunTangentX),
                                        LUXEL_MEMBER(P, sunTangentY),
                                        LUXEL_MEMBER(P, sunTangentZ),
                                        LUXEL_MEMBER(P, sunBitangentX),
                                        LUXEL_MEMBER(P, sunBitangentY),
                                        LUXEL_MEMBER(P, sunBitangentZ),
                                        LUXEL_MEMBER(P, materialFlags),
                                        LUXEL_MEMBER(P, pad0),
                                        LUXEL_MEMBER(P, pad1)}});
    using E = PathEmitterVoxel;
    expectBuffer(
        "path_trace", 15,
        {sizeof(E),
         {LUXEL_MEMBER(E, x), LUXEL_MEMBER(E, y), LUXEL_MEMBER(E, z), LUXEL_MEMBER(E, pad0)}});
    using S = PathPixelSums;
    expectBuffer(
        "path_trace", 16,
        {sizeof(S),
         {LUXEL_MEMBER(S, shiftR), LUXEL_MEMBER(S, shiftG), LUXEL_MEMBER(S, shiftB),
          LUXEL_MEMBER(S, shiftL), LUXEL_MEMBER(S, sumR), LUXEL_MEMBER(S, sumG),
          LUXEL_MEMBER(S, sumB), LUXEL_MEMBER(S, sumL), LUXEL_MEMBER(S, squaresR),
          LUXEL_MEMBER(S, squaresG), LUXEL_MEMBER(S, squaresB), LUXEL_MEMBER(S, squaresL)}});
    using M = VoxelMaterial;
    expectBuffer("path_trace", 9,
                 {sizeof(M),
                  {LUXEL_MEMBER(M, albedoR), LUXEL_MEMBER(M, albedoG), LUXEL_MEMBER(M, albedoB),
                   LUXEL_MEMBER(M, metallic), LUXEL_MEMBER(M, roughness), LUXEL_MEMBER(M, ior),
                   LUXEL_MEMBER(M, transmission), LUXEL_MEMBER(M, flags),
                   LUXEL_MEMBER(M, absorptionR), LUXEL_MEMBER(M, absorptionG),
                   LUXEL_MEMBER(M, absorptionB), LUXEL_MEMBER(M, pad0), LUXEL_MEMBER(M, emissionR),
                   LUXEL_MEMBER(M, emissionG), LUXEL_MEMBER(M, emissionB), LUXEL_MEMBER(M, pad1)}});
}

}  // namespace
}  // namespace luxel::gpu
