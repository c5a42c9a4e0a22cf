// The Vulkan runtime on whatever device is present (Mesa's lavapipe on CPU-only machines). Tests
// skip, saying why, when there is no Vulkan loader or device. Validation layers are on and any
// validation message fails the test.
#include <gtest/gtest.h>

#include <algorithm>

#include <cstring>
#include <numeric>

#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/ray_tables.h"
#include "gpu/layout_check.h"
#include "gpu/shaders/shared/hrc_layout.h"
#include "gpu/shaders/shared/rc_layout.h"
#include "luxel/core/half.h"
#include "luxel/core/rng.h"
#include "luxel/gpu/context.h"
#include "support/gpu_test_context.h"

namespace luxel::gpu {
namespace {

TEST(GpuRuntime, EmbedsEveryShader) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    const std::vector<std::string> names = embeddedShaders();
    for (const char* shader :
         {"hrc_trace", "hrc_extend", "hrc_merge", "hrc_readout", "hrc_finish", "rc_cascade"}) {
        EXPECT_NE(std::find(names.begin(), names.end(), shader), names.end()) << shader;
    }
}

TEST(GpuRuntime, ListsDevicesAndRoundTripsABuffer) {
    LUXEL_REQUIRE_GPU(context);
    auto devices = listDevices();
    ASSERT_TRUE(devices.ok());
    EXPECT_FALSE(devices->empty());
    std::printf("device: %s (%s, Vulkan %s)\n", context->device().name.c_str(),
                context->device().type.c_str(), context->device().apiVersion.c_str());

    std::vector<std::uint32_t> data(10007);
    std::iota(data.begin(), data.end(), 7u);
    auto buffer = context->createBuffer(data.size() * 4);
    ASSERT_TRUE(buffer.ok()) << buffer.error().message();
    ASSERT_TRUE(context->upload(**buffer, std::as_bytes(std::span(data))).ok());
    std::vector<std::uint32_t> back(data.size());
    ASSERT_TRUE(context->download(**buffer, std::as_writable_bytes(std::span(back))).ok());
    EXPECT_EQ(back, data);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// Transfers share one kept staging buffer that grows: uploads and downloads of growing and
// shrinking sizes, at offsets, must not see each other's bytes; fill sets every word.
TEST(GpuRuntime, TransfersOfEverySizeRoundTripAndFillSetsEveryWord) {
    LUXEL_REQUIRE_GPU(context);
    const std::size_t words = (std::size_t{3} << 20) / 4 + 5;  // past the first 1 MiB and 2 MiB
    auto buffer = context->createBuffer(words * 4);
    ASSERT_TRUE(buffer.ok()) << buffer.error().message();
    std::vector<std::uint32_t> expected(words, 0);
    std::uint32_t next = 1;
    for (std::size_t count : {std::size_t{4}, words / 3, words, std::size_t{17}, words / 2}) {
        const std::size_t offset = (count * 7) % (words - count + 1);
        std::vector<std::uint32_t> part(count);
        for (auto& w : part) w = next++;
        ASSERT_TRUE(context->upload(**buffer, std::as_bytes(std::span(part)), offset * 4).ok());
        std::copy(part.begin(), part.end(), expected.begin() + static_cast<long>(offset));
        std::vector<std::uint32_t> back(words);
        ASSERT_TRUE(context->download(**buffer, std::as_writable_bytes(std::span(back))).ok());
        ASSERT_EQ(back, expected) << "after an upload of " << count << " words at " << offset;
    }
    for (std::uint32_t word : {0u, 0x3f800000u}) {
        ASSERT_TRUE(context->fill(**buffer, word).ok());
        std::vector<std::uint32_t> back(words, 12345u);
        ASSERT_TRUE(context->download(**buffer, std::as_writable_bytes(std::span(back))).ok());
        EXPECT_EQ(back, std::vector<std::uint32_t>(words, word));
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(GpuRuntime, BadRequestsAreErrors) {
    LUXEL_REQUIRE_GPU(context);
    EXPECT_FALSE(Context::create({.device = "99", .validation = false}).ok());
    EXPECT_FALSE(Context::create({.device = "no such device", .validation = false}).ok());
    EXPECT_FALSE(context->program("no_such_shader", 1, 0).ok());
    auto huge = context->createBuffer(context->device().deviceLocalBytes * 2 + 1);
    EXPECT_FALSE(huge.ok());
}

}  // namespace
}  // namespace luxel::gpu

#include "gi2d/analytic_disk.h"
#include "gi2d/shipped_scenes.h"
#include "luxel/core/metrics.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"

namespace luxel::gpu {
namespace {

class GpuHrcScenes : public testing::TestWithParam<std::tuple<const char*, int, int>> {};

TEST_P(GpuHrcScenes, MatchesTheCpuSolver) {
    LUXEL_REQUIRE_GPU(context);
    const auto [scene, width, height] = GetParam();
    const gi2d::Medium2D medium = gi2d::testing_support::shippedScene(scene, width, height);
    for (bool blur : {true, false}) {
        gi2d::HrcOptions options;
        options.crossBlur = blur;
        const Image cpu = gi2d::solveHrc(medium, options).value();
        std::vector<PassTiming> timings;
        auto gpu = gi2d::solveHrcOnGpu(*context, medium, options, &timings);
        ASSERT_TRUE(gpu.ok()) << gpu.error().message();
        const ImageErrors e = compareImages(*gpu, cpu).value();
        std::printf("%s %dx%d blur %d: GPU vs CPU relative L1 %.2e, max %.2e (%zu passes)\n", scene,
                    width, height, blur, e.relativeL1, e.maxAbsError, timings.size());
        EXPECT_LT(e.relativeL1, 1e-5);
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuHrcScenes,
                         testing::Values(std::tuple{"penumbra.json", 128, 128},
                                         std::tuple{"fog.json", 96, 80},
                                         std::tuple{"pinhole.json", 160, 90}),
                         [](const auto& param) {
                             return gi2d::testing_support::sceneTestName(std::get<0>(param.param));
                         });

TEST(GpuHrc, DiskInVacuumFollowsTheArcsineLaw) {
    LUXEL_REQUIRE_GPU(context);
    const double R = 48.0, E = 2.0;
    const gi2d::Medium2D medium =
        gi2d::rasterize(gi2d::testing_support::analyticDiskScene(R, static_cast<float>(E))).value();
    const Image f = gi2d::solveHrcOnGpu(*context, medium).value();
    for (const auto& probe : gi2d::testing_support::diskProbes(R, E)) {
        EXPECT_NEAR(f.at(probe.x, probe.y, 0) / probe.exact, 1.0, 0.015)
            << probe.distanceOverRadius;
    }
}

// dense-fog at 96 px (0.21 per pixel after scaling): the exact near field of §12.3 acts, on both
// backends alike.
TEST(GpuHrc, ExactNearFieldMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    const gi2d::Medium2D medium =
        gi2d::testing_support::shippedScene("hard/dense-fog.json", 96, 96);
    gi2d::HrcOptions on;
    on.exactDirectLight = false;  // the near field alone: dense-fog's lamps are compact (§12.5)
    gi2d::HrcOptions off = on;
    off.exactNearField = false;
    const Image cpu = gi2d::solveHrc(medium, on).value();
    const Image cpuOff = gi2d::solveHrc(medium, off).value();
    std::vector<PassTiming> timings;
    auto gpu = gi2d::solveHrcOnGpu(*context, medium, on, &timings);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    EXPECT_TRUE(std::any_of(timings.begin(), timings.end(),
                            [](const PassTiming& t) { return t.name == "near field"; }));
    const ImageErrors e = compareImages(*gpu, cpu).value();
    const ImageErrors gathered = compareImages(cpuOff, cpu).value();
    std::printf(
        "dense-fog 96x96 near field: GPU vs CPU relative L1 %.2e, max %.2e; the gather "
        "changes the CPU's image by relative L1 %.2e\n",
        e.relativeL1, e.maxAbsError, gathered.relativeL1);
    EXPECT_GT(gathered.relativeL1, 1e-3);
    EXPECT_LT(e.relativeL1, 1e-5);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// A small bright disk (bright-disk.json at 96 px): the compact light's direct light is made on the
// CPU for both backends (§12.5); the GPU solves the rest, so the two agree as the cascades do.
TEST(GpuHrc, DirectLightMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    const gi2d::Medium2D medium =
        gi2d::testing_support::shippedScene("hard/bright-disk.json", 96, 96);
    gi2d::HrcOptions off;
    off.exactDirectLight = false;
    const Image cpu = gi2d::solveHrc(medium).value();
    const Image cpuOff = gi2d::solveHrc(medium, off).value();
    std::vector<PassTiming> timings;
    auto gpu = gi2d::solveHrcOnGpu(*context, medium, {}, &timings);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    EXPECT_TRUE(std::any_of(timings.begin(), timings.end(),
                            [](const PassTiming& t) { return t.name == "direct light (cpu)"; }));
    auto gpuOff = gi2d::solveHrcOnGpu(*context, medium, off);
    ASSERT_TRUE(gpuOff.ok()) << gpuOff.error().message();
    const ImageErrors e = compareImages(*gpu, cpu).value();
    const ImageErrors cascades = compareImages(*gpuOff, cpuOff).value();
    const ImageErrors split = compareImages(cpuOff, cpu).value();
    std::printf(
        "bright-disk 96x96 direct light: GPU vs CPU relative L1 %.2e (cascades alone %.2e); the "
        "split changes the CPU's image by %.2e\n",
        e.relativeL1, cascades.relativeL1, split.relativeL1);
    EXPECT_GT(split.relativeL1, 1e-3);
    EXPECT_LT(e.relativeL1, 1e-5);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::gpu

#include "luxel/gi2d/rc_solver.h"

namespace luxel::gpu {
namespace {

TEST(GpuRc, MatchesTheCpuSolverForBothMerges) {
    LUXEL_REQUIRE_GPU(context);
    for (const char* scene : {"penumbra.json", "fog.json"}) {
        const gi2d::Medium2D medium = gi2d::testing_support::shippedScene(scene, 96, 72);
        for (gi2d::RcMerge merge : {gi2d::RcMerge::Vanilla, gi2d::RcMerge::BilinearFix}) {
            gi2d::RcOptions options;
            options.merge = merge;
            const Image cpu = gi2d::solveRc(medium, options).value();
            std::vector<PassTiming> timings;
            auto gpu = gi2d::solveRcOnGpu(*context, medium, options, &timings);
            ASSERT_TRUE(gpu.ok()) << gpu.error().message();
            const ImageErrors e = compareImages(*gpu, cpu).value();
            std::printf("rc %s %s: GPU vs CPU relative L1 %.2e, max %.2e (%zu passes)\n", scene,
                        merge == gi2d::RcMerge::Vanilla ? "vanilla" : "fix", e.relativeL1,
                        e.maxAbsError, timings.size());
            EXPECT_LT(e.relativeL1, 1e-5);
        }
    }
    gi2d::RcOptions view;
    view.debugCascade = 2;
    const gi2d::Medium2D small = gi2d::testing_support::shippedScene("penumbra.json", 48, 48);
    const ImageErrors e = compareImages(gi2d::solveRcOnGpu(*context, small, view).value(),
                                        gi2d::solveRc(small, view).value())
                              .value();
    EXPECT_LT(e.relativeL1, 1e-4);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// Jittered probe grids (shifted cascades above 0, averaged over several shifts) on both backends.
TEST(GpuRc, JitteredProbeGridsMatchTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    const gi2d::Medium2D medium = gi2d::testing_support::shippedScene("penumbra.json", 96, 72);
    for (gi2d::RcMerge merge : {gi2d::RcMerge::Vanilla, gi2d::RcMerge::BilinearFix}) {
        gi2d::RcOptions options;
        options.merge = merge;
        options.jitters = 3;
        const Image cpu = gi2d::solveRc(medium, options).value();
        const Image gpu = gi2d::solveRcOnGpu(*context, medium, options).value();
        const ImageErrors e = compareImages(gpu, cpu).value();
        EXPECT_LT(e.relativeL1, 1e-5);
        options.jitters = 1;
        const ImageErrors plain =
            compareImages(gi2d::solveRc(medium, options).value(), cpu).value();
        EXPECT_GT(plain.relativeL1, 1e-4) << "jitter must change the image";
    }
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

TEST(GpuRc, LargeCascadesFoldIntoTwoDimensionalDispatches) {
    LUXEL_REQUIRE_GPU(context);
    // 2100 x 2048 probes at cascade 0 need more than 65535 workgroups of 64 in x.
    const gi2d::Medium2D medium = gi2d::testing_support::shippedScene("room.json", 2100, 2048);
    gi2d::RcOptions options;
    options.maxCascades = 1;  // short intervals keep this fast
    const Image cpu = gi2d::solveRc(medium, options).value();
    const Image gpu = gi2d::solveRcOnGpu(*context, medium, options).value();
    const ImageErrors e = compareImages(gpu, cpu).value();
    EXPECT_LT(e.relativeL1, 1e-5);
    EXPECT_GT(cpu.at(2099, 2047, 0) + cpu.at(1000, 1000, 1), 0.0f);
}

TEST(GpuRc, AnalyticDisk) {
    LUXEL_REQUIRE_GPU(context);
    const double R = 48.0, E = 2.0;
    const gi2d::Medium2D medium =
        gi2d::rasterize(gi2d::testing_support::analyticDiskScene(R, static_cast<float>(E))).value();
    gi2d::RcOptions options;
    options.merge = gi2d::RcMerge::BilinearFix;
    const Image f = gi2d::solveRcOnGpu(*context, medium, options).value();
    for (const auto& probe : gi2d::testing_support::diskProbes(R, E)) {
        EXPECT_NEAR(f.at(probe.x, probe.y, 0) / probe.exact, 1.0, 0.015)
            << probe.distanceOverRadius;
    }
}

}  // namespace
}  // namespace luxel::gpu
