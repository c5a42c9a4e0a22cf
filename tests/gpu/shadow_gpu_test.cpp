// Parity of the GPU sun visibility (shadow_visibility.comp.glsl, sun_visibility.glsl) with the CPU
// (SunVisibility::visibility) for every method with a GPU twin, on a small world.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gpu/shaders/shared/shadow_layout.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/shadows/sun_visibility_gpu.h"
#include "support/gpu_test_context.h"

namespace luxel::voxel {
namespace {

static_assert(LUXEL_SHADOW_HARD == unsigned(ShadowMethod::Hard));
static_assert(LUXEL_SHADOW_EXACT == unsigned(ShadowMethod::Exact));
static_assert(LUXEL_SHADOW_MSM == unsigned(ShadowMethod::Msm));
static_assert(LUXEL_SHADOW_VSM == unsigned(ShadowMethod::Vsm));
static_assert(LUXEL_SHADOW_SDF == unsigned(ShadowMethod::Sdf));
static_assert(LUXEL_SHADOW_BLEND == unsigned(ShadowMethod::Blend));
static_assert(LUXEL_SHADOW_FLOOD == unsigned(ShadowMethod::FloodFill));

// A floor, a floating slab, a thin post and a rail.
VoxelWorld parityWorld() {
    VoxelWorld world = std::move(VoxelWorld::create({24, 12, 24}, 8).value());
    for (int z = 0; z < 24; ++z)
        for (int x = 0; x < 24; ++x) {
            world.set(x, 0, z, Voxel{120, 120, 120, 255});
            if (x >= 6 && x < 14 && z >= 6 && z < 14) world.set(x, 6, z, Voxel{200, 60, 60, 255});
        }
    for (int y = 1; y < 8; ++y) world.set(18, y, 16, Voxel{90, 60, 40, 255});
    for (int x = 15; x < 22; ++x) world.set(x, 4, 18, Voxel{90, 60, 40, 255});
    world.refreshEmptySpace();
    return world;
}

// Points on the floor (facing up) and on the slab's sides, footprints across the blend band.
std::vector<ShadowQuery> parityQueries() {
    std::vector<ShadowQuery> q;
    int i = 0;
    for (double z = 1.13; z < 23; z += 0.61)
        for (double x = 1.07; x < 23; x += 0.59)
            q.push_back({{x, 1.0, z}, {0, 1, 0}, 5.0 * (i++ % 20)});
    for (double y = 6.1; y < 7; y += 0.2)
        for (double z = 6.1; z < 14; z += 0.5) q.push_back({{14.0, y, z}, {1, 0, 0}, 30.0});
    return q;
}

TEST(GpuShadowParity, EveryMethodMatchesTheCpu) {
    gpu::Context* context = test::sharedGpuContext();
    if (!context) GTEST_SKIP() << "no Vulkan device";
    const VoxelWorld world = parityWorld();
    const std::vector<ShadowQuery> queries = parityQueries();
    struct Case {
        ShadowMethod method;
        bool quantized;
        bool centres = false;  // the SDF reads the centre field instead of the cube distance
    };
    for (const Case c : {Case{ShadowMethod::Hard, false}, Case{ShadowMethod::Msm, false},
                         Case{ShadowMethod::Msm, true}, Case{ShadowMethod::Vsm, false},
                         Case{ShadowMethod::Sdf, false}, Case{ShadowMethod::Sdf, false, true},
                         Case{ShadowMethod::Blend, false}, Case{ShadowMethod::FloodFill, false}}) {
        ShadowSettings s;
        s.method = c.method;
        s.mapSize = 96;
        s.blendNear = 30;
        s.blendFar = 60;
        if (c.quantized) s.momentStorage = ShadowSettings::MomentStorage::Quantized16;
        if (c.centres) s.sdfDistance = ShadowSettings::SdfDistance::Centres;
        const SunLight sun{{0.4, 1.0, 0.3}, 3.0 * std::numbers::pi / 180.0};
        const SunVisibility cpu = std::move(SunVisibility::build(world, nullptr, sun, s).value());
        auto gpu = SunVisibilityGpu::create(*context, cpu);
        ASSERT_TRUE(gpu.ok()) << gpu.error().message();
        auto v = gpu->evaluate(queries);
        ASSERT_TRUE(v.ok()) << v.error().message();
        double sum = 0, worst = 0;
        int far = 0;
        for (std::size_t i = 0; i < queries.size(); ++i) {
            const double d = std::abs(double((*v)[i]) - cpu.visibility(queries[i]));
            sum += d;
            worst = std::max(worst, d);
            far += d > 0.05;
        }
        SCOPED_TRACE(std::string(shadowMethodName(c.method)) + (c.quantized ? " 16-bit" : "") +
                     (c.centres ? " centres" : ""));
        // Float on the GPU, double positions on the CPU: equal up to rounding, except a few
        // points where a march's step lands on the other side of a cell boundary.
        EXPECT_LT(sum / queries.size(), 2e-3);
        EXPECT_LE(far, int(queries.size() / 100));
    }
}

TEST(GpuShadowParity, ExactHasNoGpuTwin) {
    gpu::Context* context = test::sharedGpuContext();
    if (!context) GTEST_SKIP() << "no Vulkan device";
    const VoxelWorld world = parityWorld();
    ShadowSettings s;
    s.method = ShadowMethod::Exact;
    const SunVisibility cpu =
        std::move(SunVisibility::build(world, nullptr, {{0, 1, 0}, 0.01}, s).value());
    EXPECT_FALSE(SunVisibilityGpu::create(*context, cpu).ok());
}

TEST(GpuShadowParity, PenumbraSizedMomentFilterHasNoGpuTwin) {
    gpu::Context* context = test::sharedGpuContext();
    if (!context) GTEST_SKIP() << "no Vulkan device";
    const VoxelWorld world = parityWorld();
    ShadowSettings s;
    s.method = ShadowMethod::Msm;
    s.mapSize = 64;
    s.msmFilter = ShadowSettings::MsmFilter::PenumbraSized;
    const SunVisibility cpu =
        std::move(SunVisibility::build(world, nullptr, {{0, 1, 0}, 0.01}, s).value());
    auto gpu = SunVisibilityGpu::create(*context, cpu);
    ASSERT_FALSE(gpu.ok());
    EXPECT_NE(gpu.error().message().find("msm_filter"), std::string::npos);
}

}  // namespace
}  // namespace luxel::voxel
