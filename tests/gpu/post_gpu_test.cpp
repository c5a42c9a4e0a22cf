// GPU post passes against their CPU twins (bloom down/up, the whole bloom chain, the edge-aware
// upscaler), the shared push-constant layout, and the trig kernels' values on the device.
#include "luxel/post/post_gpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gpu/layout_check.h"
#include "gpu/shaders/shared/post_layout.h"
#include "gpu/shaders/shared/trig_approx.h"
#include "luxel/post/bloom.h"
#include "luxel/post/upscale.h"
#include "post/post_test_images.h"
#include "support/gpu_test_context.h"

namespace luxel::post {
namespace {

using namespace gpu::layout_check;
using gpu::shared::PostResampleParams;
using gpu::shared::PostTrigParams;

// Largest |a - b| relative to max(1, |b|).
double maxRelativeDifference(const Image& a, const Image& b) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    double worst = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        const double d = std::abs(double(a.data()[i]) - b.data()[i]);
        worst = std::max(worst, d / std::max(1.0, std::abs(double(b.data()[i]))));
    }
    return worst;
}

#define REQUIRE_GPU()                                 \
    gpu::Context* context = test::sharedGpuContext(); \
    if (!context) GTEST_SKIP() << "no Vulkan device";

TEST(PostGpu, SharedLayouts) {
    LUXEL_REQUIRE_EMBEDDED_SHADERS();
    const CppLayout resample{
        sizeof(PostResampleParams),
        {LUXEL_MEMBER(PostResampleParams, srcWidth), LUXEL_MEMBER(PostResampleParams, srcHeight),
         LUXEL_MEMBER(PostResampleParams, dstWidth), LUXEL_MEMBER(PostResampleParams, dstHeight),
         LUXEL_MEMBER(PostResampleParams, karis), LUXEL_MEMBER(PostResampleParams, pad0),
         LUXEL_MEMBER(PostResampleParams, baseWeight),
         LUXEL_MEMBER(PostResampleParams, lowWeight)}};
    for (const char* shader : {"post_bloom_down", "post_bloom_up", "post_upscale"}) {
        expectPushConstants(shader, resample);
        EXPECT_EQ(reflect(shader).workgroupSize,
                  (std::array<std::uint32_t, 3>{LUXEL_POST_GROUP, LUXEL_POST_GROUP, 1}));
    }
    expectPushConstants(
        "post_trig_timing",
        {sizeof(PostTrigParams),
         {LUXEL_MEMBER(PostTrigParams, count), LUXEL_MEMBER(PostTrigParams, iterations),
          LUXEL_MEMBER(PostTrigParams, function), LUXEL_MEMBER(PostTrigParams, terms)}});
}

TEST(PostGpu, BloomPassesMatchTheCpu) {
    REQUIRE_GPU();
    for (auto [w, h] : {std::pair{64, 48}, std::pair{37, 21}}) {
        const Image src = test::randomHdr(w, h, 7);
        for (bool karis : {false, true}) {
            auto gpuDown = bloomDownsampleGpu(*context, src, karis);
            ASSERT_TRUE(gpuDown.ok()) << gpuDown.error().message();
            EXPECT_LT(maxRelativeDifference(*gpuDown, bloomDownsample(src, karis)), 1e-5);
        }
        const Image low = bloomDownsample(src, false);
        auto gpuUp = bloomUpsampleAddGpu(*context, low, src, 0.25f, 0.75f);
        ASSERT_TRUE(gpuUp.ok()) << gpuUp.error().message();
        EXPECT_LT(maxRelativeDifference(*gpuUp, bloomUpsampleAdd(low, src, 0.25f, 0.75f)), 1e-5);
    }
}

TEST(PostGpu, WholeBloomMatchesTheCpu) {
    REQUIRE_GPU();
    const Image src = test::randomHdr(80, 50, 3);
    std::vector<gpu::PassTiming> timings;
    const BloomSettings settings{0.4f, 4, true};
    auto gpuBloom = bloomGpu(*context, src, settings, &timings);
    ASSERT_TRUE(gpuBloom.ok()) << gpuBloom.error().message();
    EXPECT_LT(maxRelativeDifference(*gpuBloom, bloom(src, settings)), 1e-5);
    EXPECT_EQ(timings.size(), 4u + 3u + 1u);  // 4 down, 3 up, 1 combine
}

TEST(PostGpu, EdgeUpscalerMatchesTheCpu) {
    REQUIRE_GPU();
    const Image src = test::randomHdr(40, 24, 11);
    for (auto [w, h] : {std::pair{80, 48}, std::pair{97, 61}}) {
        auto gpuUp = upscaleEdgeGpu(*context, src, w, h);
        ASSERT_TRUE(gpuUp.ok()) << gpuUp.error().message();
        EXPECT_LT(maxRelativeDifference(*gpuUp, upscaleEdge(src, w, h)), 1e-4) << w << "x" << h;
    }
}

TEST(PostGpu, TrigKernelsAgreeWithTheirCpuTwins) {
    REQUIRE_GPU();
    std::vector<float> x;
    for (int i = 0; i <= 200; ++i) x.push_back(-1.0f + i * 0.01f);
    auto taylor = trigGpu(*context, x, TrigFunction::TaylorAsin, 6, 1);
    ASSERT_TRUE(taylor.ok()) << taylor.error().message();
    auto minimax = trigGpu(*context, x, TrigFunction::MinimaxAsin, 0, 1);
    ASSERT_TRUE(minimax.ok());
    auto builtin = trigGpu(*context, x, TrigFunction::Asin, 0, 1);
    ASSERT_TRUE(builtin.ok());
    double builtinError = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        EXPECT_NEAR(taylor->values[i], gpu::shared::taylorAsin(x[i], 6), 1e-5f) << x[i];
        EXPECT_NEAR(minimax->values[i], gpu::shared::minimaxAsin8(x[i]), 1e-6f) << x[i];
        builtinError =
            std::max(builtinError, std::abs(double(builtin->values[i]) - std::asin(double(x[i]))));
    }
    // Vulkan leaves asin's precision to its atan-based definition (4096 ULP for atan); lavapipe's
    // built-in is off by up to 4e-4 rad (docs/algorithms/trig-approximations.md).
    EXPECT_LT(builtinError, 2e-3) << context->device().name;
    std::printf("built-in asin on %s: max error %.3g rad\n", context->device().name.c_str(),
                builtinError);
}

TEST(PostGpu, LinearDispatchesPastOneRowOfWorkgroupsReachEveryInvocation) {
    REQUIRE_GPU();
    // More invocations than 65535 workgroups of 64 hold: Context::run folds them into two rows
    // (gpu::Dispatch::setLinearThreads), and the shader's LUXEL_LINEAR_INVOCATION unfolds them.
    const std::size_t count = std::size_t{65535} * 64 + 1000;
    std::vector<float> x(count);
    for (std::size_t i = 0; i < count; ++i) x[i] = float(i % 2001) * 0.001f - 1.0f;
    auto minimax = trigGpu(*context, x, TrigFunction::MinimaxAsin, 0, 1);
    ASSERT_TRUE(minimax.ok()) << minimax.error().message();
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < count; ++i) {
        wrong += std::abs(minimax->values[i] - gpu::shared::minimaxAsin8(x[i])) > 1e-6f;
    }
    EXPECT_EQ(wrong, 0u) << "of " << count;
}

}  // namespace
}  // namespace luxel::post
