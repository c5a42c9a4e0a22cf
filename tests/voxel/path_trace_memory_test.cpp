// The path tracers' memory estimates (estimatePathTraceMemory, estimatePathTraceGpuMemory): the
// bytes per pixel and per emitter, the world's upload, and the CPU tracer's refusal, with the
// bytes, of running sums that do not fit (under a lowered address-space limit).
#include <gtest/gtest.h>

#include <string>

#include "gpu/shaders/shared/path_trace_layout.h"
#include "luxel/core/memory.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/path_trace_gpu.h"
#include "luxel/voxel/voxel_gpu.h"
#include "support/memory_limit.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr std::uint64_t kMiB = 1024 * 1024;

TEST(PathTraceMemory, EstimatesCountTheSumsTheWorldAndTheEmitters) {
    const std::uint64_t pixels = 320 * 180;
    const PathTraceMemory cpu = estimatePathTraceMemory(320, 180);
    EXPECT_EQ(cpu.host, pixels * 64);  // 8 doubles a pixel
    EXPECT_EQ(cpu.device(), 0u);
    const VoxelWorld world = makeWorld({40, 16, 24});
    const PathTraceMemory gpu = estimatePathTraceGpuMemory(world, nullptr, 320, 180, 3);
    EXPECT_EQ(gpu.host, pixels * (64 + 48));  // the double sums and one download of float ones
    EXPECT_EQ(gpu.sums, pixels * sizeof(gpu::shared::PathPixelSums));
    EXPECT_EQ(gpu.sums, pixels * 48);
    EXPECT_EQ(gpu.emitters, 3 * sizeof(gpu::shared::PathEmitterVoxel));
    // The world as the ray caster uploads it, without its image (the path tracer writes none).
    EXPECT_EQ(gpu.world, estimateVoxelGpuMemory(world.size(), world.chunkSize(), nullptr, 0, 0));
    EXPECT_EQ(gpu.world + 320 * 180 * 16,
              estimateVoxelGpuMemory(world.size(), world.chunkSize(), nullptr, 320, 180));
    EXPECT_EQ(gpu.device(), gpu.world + gpu.sums + gpu.emitters);
    // No emitters still bind a one-voxel placeholder.
    EXPECT_EQ(estimatePathTraceGpuMemory(world, nullptr, 4, 4, 0).emitters, 16u);
}

TEST(PathTraceMemory, TheCpuTracerRefusesSumsThatDoNotFit) {
    // 8192 x 8192 pixels of 64 bytes: 4 GiB of running sums, with 256 MiB to spare.
    const int code = luxel::test::runUnderMemoryLimit(256 * kMiB, [] {
        const VoxelWorld world = floorWorld();
        const Camera camera = *Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 8192, 8192);
        auto tracer = PathTracer::create(world, camera, plainLight(0.5f, Rgb(0.0f), Rgb(1.0f)), {});
        if (tracer.ok()) return 1;
        const std::string& m = tracer.error().message();
        return m.rfind("path tracing 8192x8192 (the running sums) needs 4.0 GiB, only ", 0) == 0
                   ? 0
                   : 2;
    });
    EXPECT_EQ(code, 0);
    // The same tracer fits when the image is small.
    auto small = PathTracer::create(floorWorld(),
                                    *Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 64, 64),
                                    plainLight(0.5f, Rgb(0.0f), Rgb(1.0f)), {});
    EXPECT_TRUE(small.ok()) << small.error().message();
}

}  // namespace
