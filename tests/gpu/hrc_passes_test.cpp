// Each HRC GPU pass against its CPU twin (src/gi2d/hrc/gpu_passes.h), on the same inputs: a random
// volumetric medium, so every pass sees partial transmittance, emission and out-of-frame reads.
// Runs on whatever Vulkan device is present (lavapipe on CPU-only machines; skipped, saying why,
// without one). Validation layers are on and any message fails the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/finish.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/gpu_passes.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/near_lights.h"
#include "gi2d/hrc/ray_tables.h"
#include "gi2d/hrc/readout.h"
#include "gpu/random_medium.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/half.h"
#include "luxel/core/rng.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gpu/context.h"

namespace luxel::gi2d::hrc {
namespace {

class HrcPasses : public ::testing::Test {
  protected:
    void SetUp() override {
        auto c = gpu::Context::create({.device = "", .validation = true});
        if (!c) GTEST_SKIP() << "no Vulkan device: " << c.error().message();
        context_ = std::move(*c);
    }
    void TearDown() override {
        if (context_) {
            EXPECT_EQ(context_->validationMessages(), 0) << context_->lastValidationMessage();
        }
    }
    std::unique_ptr<gpu::Context> context_;
};

// Non-square, not a power of two, with partly transparent emitting pixels everywhere and a sky.
Medium2D randomMedium(int w, int h, std::uint64_t seed) {
    return testing::randomMedium(w, h, seed, Rgb(0.2f, 0.3f, 0.4f));
}

// Largest |a - b| relative to max(1, |a|) over two float arrays of the same size.
float worstRelative(const float* a, const float* b, std::size_t n) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(1.0f, std::abs(a[i])));
    }
    return worst;
}

// Two binary16 cone buffers of the same shape: the largest |a - b| relative to max(1, |a|) over
// the values that differ by more than one rounding step, and how many differ by exactly one (the
// same float sum, give or take the last bit, rounded to the two halves either side of a midpoint).
struct ConeDifference {
    float worst = 0.0f;
    std::size_t roundingSteps = 0;
};
ConeDifference compareCones(std::span<const std::uint16_t> a, std::span<const std::uint16_t> b) {
    ConeDifference d;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const bool sameSign = ((a[i] ^ b[i]) & 0x8000u) == 0;
        if (sameSign && std::abs(int{a[i]} - int{b[i]}) == 1) {
            ++d.roundingSteps;
            continue;
        }
        const float x = halfToFloat(a[i]), y = halfToFloat(b[i]);
        d.worst = std::max(d.worst, std::abs(x - y) / std::max(1.0f, std::abs(x)));
    }
    return d;
}

float worstRelativeHalves(std::span<const std::uint16_t> a, std::span<const std::uint16_t> b) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const float x = halfToFloat(a[i]), y = halfToFloat(b[i]);
        worst = std::max(worst, std::abs(x - y) / std::max(1.0f, std::abs(x)));
    }
    return worst;
}

TEST_F(HrcPasses, TraceMatchesTraceLevelInEveryFrustum) {
    // The GPU marches the canvas medium through each frustum's frame; the CPU marches the frame
    // medium (frameMedium), which carries no boundary radiance: the sky enters HRC in the merge,
    // and hrc_trace, like the solver's marcher, treats the outside as empty space.
    const Medium2D medium = randomMedium(40, 28, 5);
    for (int f = 0; f < 4; ++f) {
        const FrustumFrame frame = makeFrame(static_cast<Frustum>(f), 40, 28);
        const RayMarcher marcher(frameMedium(medium, frame));
        RayTables cpu, gpu;
        cpu.reset(frame.length, frame.rows, 4);
        gpu.reset(frame.length, frame.rows, 4);
        for (int n = 0; n < 4; ++n) {
            // Cascade 0 with its depth scale
            // (docs/algorithms/holographic-radiance-cascades.md §3.1).
            const float scale = gpu::shared::hrcTracedDepthScale(n, 4);
            traceLevel(cpu, marcher, n, scale);
            auto ms = traceLevelOnGpu(*context_, medium, frame, gpu, n, scale);
            ASSERT_TRUE(ms.ok()) << ms.error().message();
            // The same exact DDA in float on both sides; the entries are binary16.
            const float worst = worstRelativeHalves(cpu.levelHalves(n), gpu.levelHalves(n));
            std::printf("frustum %d, trace T%d: worst relative difference %.2e\n", f, n, worst);
            EXPECT_LT(worst, 2e-3f) << "frustum " << f << " level " << n;
        }
    }
}

TEST_F(HrcPasses, ExtendMatchesExtendLevel) {
    const Medium2D medium = randomMedium(96, 80, 11);
    const RayMarcher marcher(medium);
    RayTables cpu, gpu;
    cpu.reset(96, 80, 6);
    gpu.reset(96, 80, 6);
    traceBaseLevels(cpu, marcher, 3);
    traceBaseLevels(gpu, marcher, 3);
    for (int n = 3; n < 6; ++n) {
        extendLevel(cpu, n);
        auto ms = extendLevelOnGpu(*context_, gpu, n);
        ASSERT_TRUE(ms.ok()) << ms.error().message();
        // Same arithmetic in float; at most one binary16 rounding step apart.
        EXPECT_LT(worstRelativeHalves(cpu.levelHalves(n), gpu.levelHalves(n)), 1e-3f)
            << "level " << n;
    }
}

TEST_F(HrcPasses, MergeMatchesMergeCascade) {
    const Medium2D medium = randomMedium(48, 36, 7);
    const RayMarcher marcher(medium);
    RayTables tables;
    const int levels = cascadeCount(48);
    tables.reset(48, 36, levels);
    traceBaseLevels(tables, marcher, 3);
    extendLevels(tables, 3);
    const Rgb sky = medium.boundaryRadiance;
    // Every level top-down, each side fed the CPU's upper buffer, so each level is compared alone.
    ConeBuffer upperCpu;
    for (int n = levels - 1; n >= 0; --n) {
        ConeBuffer cpu, gpu;
        const ConeBuffer* upper = n == levels - 1 ? nullptr : &upperCpu;
        mergeCascade(tables, n, upper, sky, cpu);
        auto ms = mergeCascadeOnGpu(*context_, tables, n, upper, sky, gpu);
        ASSERT_TRUE(ms.ok()) << ms.error().message();
        ASSERT_EQ(cpu.halves().size(), gpu.halves().size());
        // The cones are binary16: a float sum the two sides compute a last bit apart may round
        // to neighbouring halves. Those are counted, and must stay rare; every other value must
        // agree as the float sums did.
        const ConeDifference d = compareCones(cpu.halves(), gpu.halves());
        std::printf(
            "merge R%d: worst relative difference %.2e, %zu of %zu values one binary16 "
            "step apart\n",
            n, d.worst, d.roundingSteps, cpu.halves().size());
        EXPECT_LT(d.worst, 1e-4f) << "level " << n;
        EXPECT_LE(d.roundingSteps * 1000, cpu.halves().size()) << "level " << n;
        upperCpu = std::move(cpu);
    }
}

TEST_F(HrcPasses, MergeNearLightsMatchesMergeCascade) {
    // Cascade 0 next to lights (§12.3): the near probe's row blend weighed by the mask read at
    // the pixel each plane is read out for, in every frustum's frame.
    const int w = 45, h = 33;
    const Medium2D medium = randomMedium(w, h, 17);
    Medium2D lights{Image(w, h, 3), Image(w, h, 3), Rgb{}};
    for (const auto& [x, y] : {std::pair{3, 4}, std::pair{20, 16}, std::pair{21, 17},
                               std::pair{44, 30}, std::pair{0, 32}}) {
        lights.emission.setRgb(x, y, {4.0f, 4.0f, 4.0f});
        lights.absorption.setRgb(x, y, {1.0f, 1.0f, 1.0f});
    }
    const NearLightMask mask = NearLightMask::fromMedium(lights);
    for (int r = 0; r < 4; ++r) {
        const FrustumFrame frame = makeFrame(static_cast<Frustum>(r), w, h);
        RayTables tables;
        const int levels = cascadeCount(frame.length);
        tables.reset(frame.length, frame.rows, levels);
        traceBaseLevels(tables, RayMarcher(frameMedium(medium, frame)), 3);
        extendLevels(tables, 3);
        const Rgb sky = medium.boundaryRadiance;
        ConeBuffer upper, cpu, gpu, whole;
        for (int n = levels - 1; n >= 1; --n) {
            mergeCascade(tables, n, n == levels - 1 ? nullptr : &upper, sky, cpu);
            upper = std::move(cpu);
        }
        mergeCascade(tables, 0, &upper, sky, cpu, {&mask, frame});
        mergeCascade(tables, 0, &upper, sky, whole);
        auto ms = mergeCascadeOnGpu(*context_, tables, 0, &upper, sky, gpu, {&mask, frame});
        ASSERT_TRUE(ms.ok()) << ms.error().message();
        ASSERT_EQ(cpu.halves().size(), gpu.halves().size());
        const ConeDifference d = compareCones(cpu.halves(), gpu.halves());
        EXPECT_LT(d.worst, 1e-4f) << "frustum " << r;
        EXPECT_LE(d.roundingSteps * 1000, cpu.halves().size()) << "frustum " << r;
        // The mask changes the cones next to the lights and nowhere else.
        std::size_t changed = 0;
        for (std::size_t v = 0; v < cpu.halves().size(); ++v) {
            changed += cpu.halves()[v] != whole.halves()[v];
        }
        EXPECT_GT(changed, 0u) << "frustum " << r;
        EXPECT_LT(changed, cpu.halves().size() / 10) << "frustum " << r;
    }
}

TEST_F(HrcPasses, ReadoutMatchesReadOut) {
    const int w = 37, h = 23;
    for (int r = 0; r < 4; ++r) {
        const FrustumFrame frame = makeFrame(static_cast<Frustum>(r), w, h);
        ConeBuffer cones;
        cones.reset(frame.length, 1, frame.rows);  // R_0: one cone per plane
        Pcg32 rng(r + 1);
        for (int p = 0; p < cones.planes(); ++p) {
            for (int y = 0; y < cones.rows(); ++y) {
                cones.set(p, 0, y, Rgb(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()));
            }
        }
        Image cpu(w, h, 3), gpu(w, h, 3);
        for (std::size_t i = 0; i < cpu.size(); ++i) cpu.data()[i] = gpu.data()[i] = 0.25f;
        const Rgb sky(0.5f, 0.25f, 2.0f);
        readOut(frame, cones, 0, sky, cpu);
        auto ms = readOutOnGpu(*context_, frame, cones, sky, gpu);
        ASSERT_TRUE(ms.ok()) << ms.error().message();
        EXPECT_LT(worstRelative(cpu.data(), gpu.data(), cpu.size()), 1e-6f) << "frustum " << r;
    }
}

TEST_F(HrcPasses, FinishMatchesFinishFluence) {
    const Medium2D medium = randomMedium(45, 31, 13);
    Image beyond(45, 31, 3);
    Pcg32 rng(17);
    for (std::size_t i = 0; i < beyond.size(); ++i) beyond.data()[i] = rng.nextFloat() * 4.0f;
    for (bool blur : {false, true}) {
        const Image cpu = finishFluence(medium, beyond, 4, blur);
        Image gpu;
        auto ms = finishOnGpu(*context_, medium, beyond, 4, blur, gpu);
        ASSERT_TRUE(ms.ok()) << ms.error().message();
        const float worst = worstRelative(cpu.data(), gpu.data(), cpu.size());
        std::printf("finish (blur %d): worst relative difference %.2e\n", blur, worst);
        EXPECT_LT(worst, 1e-5f) << "blur " << blur;
    }
}

}  // namespace
}  // namespace luxel::gi2d::hrc
