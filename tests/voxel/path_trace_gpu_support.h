// Helpers of the GPU path tracer's tests (path_trace_gpu_test.cpp,
// path_trace_gpu_materials_test.cpp): the shared Vulkan context or a skip, the CPU and GPU
// images of the same options, and their parity within the standard errors.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "luxel/gpu/context.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/path_trace_gpu.h"
#include "support/gpu_test_context.h"

namespace luxel::voxel::test {

// The shared context, or a skip saying why there is none.
#define REQUIRE_CONTEXT(context)                               \
    gpu::Context* context = ::luxel::test::sharedGpuContext(); \
    if (!context) GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message()

inline PathTraceImage traceCpu(const VoxelWorld& world, const Camera& camera, const ShadeOptions& o,
                               const PathTraceOptions& p, const TextureSet* textures = nullptr) {
    auto image = pathTrace(world, camera, o, p, textures);
    EXPECT_TRUE(image.ok()) << image.error().message();
    return image.ok() ? std::move(*image) : PathTraceImage{};
}

inline PathTraceImage traceGpu(gpu::Context& context, const VoxelWorld& world, const Camera& camera,
                               const ShadeOptions& o, const PathTraceOptions& p,
                               const TextureSet* textures = nullptr) {
    auto image = pathTraceGpu(context, world, camera, o, p, textures);
    EXPECT_TRUE(image.ok()) << image.error().message();
    if (!image.ok()) return {};
    EXPECT_EQ(context.validationMessages(), 0) << context.lastValidationMessage();
    return std::move(*image);
}

// The CPU and GPU images of the same samples: within their standard errors, and nearly all
// equal (the same random numbers; only paths that graze an edge in float go another way).
inline void expectSameSamples(const PathTraceImage& cpu, const PathTraceImage& gpu,
                              const char* name) {
    ASSERT_EQ(gpu.samplesPerPixel, cpu.samplesPerPixel) << name;
    ASSERT_EQ(gpu.radiance.width(), cpu.radiance.width()) << name;
    ASSERT_EQ(gpu.radiance.height(), cpu.radiance.height()) << name;
    const int w = cpu.radiance.width(), h = cpu.radiance.height();
    int within = 0, close = 0;
    double cpuMean = 0.0, gpuMean = 0.0, worst = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const double a = cpu.radiance.at(x, y, c), b = gpu.radiance.at(x, y, c);
                const double se =
                    std::hypot(cpu.standardError.at(x, y, c), gpu.standardError.at(x, y, c));
                within += std::abs(a - b) <= 4.0 * se + 1e-5 * std::abs(a);
                close += std::abs(a - b) <= 1e-4 * std::abs(a) + 1e-6;
                worst = std::max(worst, std::abs(a - b) / (se + 1e-9));
                cpuMean += a, gpuMean += b;
            }
    const int values = w * h * 3;
    std::printf(
        "%s: %d of %d values within 4 SE, %d equal to 1e-4, worst %.2f SE, image means "
        "%.6f (cpu) %.6f (gpu), relative error %.4f %.4f\n",
        name, within, values, close, worst, cpuMean / values, gpuMean / values, cpu.relativeError,
        gpu.relativeError);
    EXPECT_GE(within, values * 99 / 100) << name;
    EXPECT_GE(close, values * 9 / 10) << name;
    EXPECT_GT(cpuMean, 0.0) << name;
    EXPECT_NEAR(gpuMean, cpuMean, 0.01 * cpuMean) << name;
    EXPECT_NEAR(gpu.relativeError, cpu.relativeError, 0.05 * cpu.relativeError) << name;
}

// The CPU and GPU tracers' images of the same options (expectSameSamples).
inline void expectParity(gpu::Context& context, const VoxelWorld& world, const Camera& camera,
                         const ShadeOptions& o, const PathTraceOptions& p,
                         const TextureSet* textures, const char* name) {
    const PathTraceImage cpu = traceCpu(world, camera, o, p, textures);
    const PathTraceImage gpu = traceGpu(context, world, camera, o, p, textures);
    ASSERT_EQ(gpu.samplesPerPixel, p.samplesPerPixel);
    expectSameSamples(cpu, gpu, name);
}

}  // namespace luxel::voxel::test
