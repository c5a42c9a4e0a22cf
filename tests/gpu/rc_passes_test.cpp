// The RC GPU pass (rc_cascade) against its CPU twin (cascadePass in src/gi2d/rc/rc_cascade_pass.h)
// cascade by cascade, both merges, each level fed the CPU's upper cascade so every level is
// compared alone. Runs on whatever Vulkan device is present (lavapipe on CPU-only machines;
// skipped, saying why, without one). Validation layers are on and any message fails the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gi2d/rc/rc_cascade_pass.h"
#include "gpu/layout_check.h"
#include "gpu/random_medium.h"
#include "gpu/shaders/shared/rc_layout.h"
#include "luxel/core/rng.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d::rc {
namespace {

Medium2D randomMedium(int w, int h, std::uint64_t seed) {
    return testing::randomMedium(w, h, seed, Rgb(0.3f, 0.2f, 0.1f));
}

TEST(RcPasses, CascadePassMatchesTheCpuTwinAtEveryLevel) {
    auto context = gpu::Context::create({.device = "", .validation = true});
    if (!context) GTEST_SKIP() << "no Vulkan device: " << context.error().message();
    const Medium2D medium = randomMedium(45, 33, 3);
    const RayMarcher marcher(medium);
    const std::vector<RcCascade> cascades = rcCascades(45, 33, RcOptions{});
    ASSERT_GE(cascades.size(), 3u);
    for (RcMerge merge : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
        std::vector<Rgb> upper;
        for (int i = static_cast<int>(cascades.size()) - 1; i >= 0; --i) {
            const std::vector<Rgb> cpu =
                cascadePass(marcher, cascades, i, upper, medium.boundaryRadiance, merge);
            std::vector<Rgb> gpu;
            auto ms = cascadePassOnGpu(**context, medium, cascades, i, upper, merge, gpu);
            ASSERT_TRUE(ms.ok()) << ms.error().message();
            ASSERT_EQ(cpu.size(), gpu.size());
            // Double-precision DDA on the CPU, float on the GPU: the same intervals to rounding.
            double sumAbs = 0, sumRef = 0;
            float worst = 0;
            for (std::size_t v = 0; v < cpu.size(); ++v) {
                for (int c = 0; c < 3; ++c) {
                    const float d = std::abs(cpu[v][c] - gpu[v][c]);
                    sumAbs += d;
                    sumRef += std::abs(cpu[v][c]);
                    worst = std::max(worst, d / std::max(1.0f, std::abs(cpu[v][c])));
                }
            }
            const double relL1 = sumAbs / sumRef;
            std::printf("%s cascade %d: relative L1 %.2e, worst %.2e\n",
                        merge == RcMerge::Vanilla ? "vanilla" : "fix", i, relL1, worst);
            EXPECT_LT(relL1, 1e-5) << "cascade " << i;
            EXPECT_LT(worst, 1e-3f) << "cascade " << i;
            upper = cpu;
        }
    }
    EXPECT_EQ((*context)->validationMessages(), 0) << (*context)->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::gi2d::rc
