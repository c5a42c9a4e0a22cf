// The voxel radiance cascades' lighting passes on the GPU against their CPU reference
// (RadianceCascades::iterate): a sunlit room with a window, a sky and a lamp, pass by pass, and
// light changed in between; the same room with glass in its window and a glass block inside
// (chains through glass). Runs on lavapipe where there is no hardware GPU.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/radiance_cascades_gpu.h"
#include "support/gpu_test_context.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

// Glass in the window and a glass block on the floor: texture slot 1.
VoxelWorld roomWithWindow(bool glass = false) {
    auto created = VoxelWorld::create({20, 12, 20}, 8);
    EXPECT_TRUE(created.ok());
    VoxelWorld world = std::move(*created);
    for (int z = 0; z < 20; ++z)
        for (int x = 0; x < 20; ++x) world.set(x, 0, z, Voxel{200, 190, 170, 255});
    for (int z = 3; z <= 15; ++z)
        for (int y = 1; y <= 7; ++y)
            for (int x = 3; x <= 15; ++x) {
                const bool wall = x == 3 || x == 15 || z == 3 || z == 15 || y == 7;
                const bool window = z == 3 && y >= 3 && y <= 5 && x >= 6 && x <= 11;
                if (wall && !window) world.set(x, y, z, Voxel{220, 220, 220, 255});
                if (window && glass) world.set(x, y, z, Voxel{230, 240, 255, 2});
            }
    world.set(8, 1, 10, Voxel{255, 255, 255, 1});  // texture slot 0: a lamp
    if (glass) {
        for (int y = 1; y <= 3; ++y)
            for (int x = 10; x <= 12; ++x) world.set(x, y, 6, Voxel{255, 255, 255, 2});
    }
    world.refreshEmptySpace();
    return world;
}

ShadeOptions light() {
    ShadeOptions o;
    o.textures = false;
    o.skyHorizon = Rgb(0.8f, 0.85f, 1.0f);
    o.skyTop = Rgb(0.2f, 0.4f, 0.9f);
    o.sunIrradiance = Rgb(6.0f, 5.8f, 5.4f);
    o.sunDirection = {0.1f, 0.6f, -1.0f};
    Material plain;
    plain.name = "plain";
    plain.albedo = Rgb(0.8f);
    EXPECT_TRUE(o.materials.setPlain(plain).ok());
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = Rgb(8.0f, 6.0f, 3.0f);
    EXPECT_TRUE(o.materials.setSlot(0, lamp).ok());
    Material glass;
    glass.name = "glass";
    glass.ior = 1.5f;
    glass.roughness = 0.0f;
    glass.transmission = 1.0f;
    glass.absorption = Rgb(0.05f, 0.02f, 0.01f);
    EXPECT_TRUE(o.materials.setSlot(1, glass).ok());
    return o;
}

// Largest relative difference of the irradiance the two give on a sample of faces' points.
double largestDifference(const RadianceCascades& a, const RadianceCascades& b, double& scale) {
    double largest = 0.0;
    scale = 0.0;
    for (int z = 4; z < 15; ++z)
        for (int x = 4; x < 15; ++x) {
            const Rgb ea = a.indirectIrradiance({x, 0, z}, {0, 1, 0}, {x + 0.3, 1.0, z + 0.6});
            const Rgb eb = b.indirectIrradiance({x, 0, z}, {0, 1, 0}, {x + 0.3, 1.0, z + 0.6});
            for (int c = 0; c < 3; ++c) {
                largest = std::max(largest, double(std::abs(ea[c] - eb[c])));
                scale = std::max(scale, double(std::abs(eb[c])));
            }
        }
    return largest;
}

// The same cascades twice, the second with its passes on the GPU.
struct Twins {
    std::optional<RadianceCascades> cpu, onGpu;
    std::optional<RadianceCascadesGpu> gpu;  // empty when either could not be made
};

Twins makeTwins(gpu::Context& context, const VoxelWorld& world, const ShadeOptions& o) {
    Twins t;
    auto cpu = RadianceCascades::create(world, nullptr, o);
    auto onGpu = RadianceCascades::create(world, nullptr, o);
    EXPECT_TRUE(cpu.ok() && onGpu.ok());
    if (!cpu.ok() || !onGpu.ok()) return t;
    t.cpu.emplace(std::move(*cpu));
    t.onGpu.emplace(std::move(*onGpu));
    auto gpu = RadianceCascadesGpu::create(context, *t.onGpu);
    EXPECT_TRUE(gpu.ok()) << gpu.error().message();
    if (gpu.ok()) t.gpu.emplace(std::move(*gpu));
    return t;
}

// One pass and then three more on both: the GPU's irradiance (downloaded into `onGpu`) within
// 1e-5 of the largest of the CPU's after each.
void expectOneThenThreePassesMatch(RadianceCascades& cpu, RadianceCascades& onGpu,
                                   RadianceCascadesGpu& gpu) {
    for (int passes : {1, 3}) {
        for (int i = 0; i < passes; ++i) cpu.iterate();
        auto ran = gpu.iterate(passes);
        ASSERT_TRUE(ran.ok()) << ran.error().message();
        ASSERT_TRUE(gpu.download().ok());
        double scale = 0.0;
        const double difference = largestDifference(onGpu, cpu, scale);
        EXPECT_GT(scale, 0.1);
        EXPECT_LE(difference, 1e-5 * scale) << passes;
    }
}

TEST(RadianceCascadesGpu, PassesMatchTheCpuReference) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = roomWithWindow();
    ShadeOptions o = light();
    Twins t = makeTwins(*context, world, o);
    ASSERT_TRUE(t.gpu);
    RadianceCascades &cpu = *t.cpu, &onGpu = *t.onGpu;
    RadianceCascadesGpu& gpu = *t.gpu;
    expectOneThenThreePassesMatch(cpu, onGpu, gpu);
    // New light: the sun moves; both carry their irradiance into the next passes.
    o.sunDirection = {-0.4f, 0.7f, -1.0f};
    ASSERT_TRUE(cpu.setLight(o).ok());
    ASSERT_TRUE(onGpu.setLight(o).ok());
    ASSERT_TRUE(gpu.uploadLight().ok());
    for (int i = 0; i < 2; ++i) cpu.iterate();
    ASSERT_TRUE(gpu.iterate(2).ok());
    ASSERT_TRUE(gpu.download().ok());
    double scale = 0.0;
    const double difference = largestDifference(onGpu, cpu, scale);
    EXPECT_GT(scale, 0.1);
    EXPECT_LE(difference, 1e-5 * scale);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// iterateOnce, the viewer's frame: one pass, downloaded, and the pass's relative change as the
// CPU's iterate returns it.
TEST(RadianceCascadesGpu, OnePassAtATimeReportsTheCpusChange) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = roomWithWindow();
    const ShadeOptions o = light();
    Twins t = makeTwins(*context, world, o);
    ASSERT_TRUE(t.gpu);
    RadianceCascades &cpu = *t.cpu, &onGpu = *t.onGpu;
    RadianceCascadesGpu& gpu = *t.gpu;
    for (int pass = 1; pass <= 4; ++pass) {
        const double expected = cpu.iterate();
        auto change = gpu.iterateOnce();
        ASSERT_TRUE(change.ok()) << change.error().message();
        EXPECT_GT(expected, 0.0) << pass;
        EXPECT_NEAR(*change, expected, 1e-4 * expected + 1e-9) << pass;
        double scale = 0.0;
        const double difference = largestDifference(onGpu, cpu, scale);
        EXPECT_LE(difference, 1e-5 * scale) << pass;
    }
    EXPECT_EQ(onGpu.stats().bounces, 4);
}

TEST(RadianceCascadesGpu, PassesThroughGlassMatchTheCpuReference) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = roomWithWindow(true);
    const ShadeOptions o = light();
    Twins t = makeTwins(*context, world, o);
    ASSERT_TRUE(t.gpu);
    RadianceCascades &cpu = *t.cpu, &onGpu = *t.onGpu;
    RadianceCascadesGpu& gpu = *t.gpu;
    expectOneThenThreePassesMatch(cpu, onGpu, gpu);
    EXPECT_GT(cpu.stats().passages, 0u);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

// Refraction turned off after the cascades were made: setLight builds their faces (none under
// glass now) and segments again. The GPU passes made before refuse to run on the stale tables;
// made again, they match a fresh CPU build with the new light.
TEST(RadianceCascadesGpu, PassesAfterRefractionIsTurnedOffMatchAFreshBuild) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = roomWithWindow(true);
    const ShadeOptions on = light();
    ShadeOptions off = on;
    off.refraction = false;
    Twins t = makeTwins(*context, world, on);
    ASSERT_TRUE(t.gpu);
    RadianceCascades& onGpu = *t.onGpu;
    auto fresh = RadianceCascades::create(world, nullptr, off);
    ASSERT_TRUE(fresh.ok()) << fresh.error().message();
    ASSERT_GT(onGpu.stats().faces, fresh->stats().faces);  // the floor under the glass block
    ASSERT_TRUE(onGpu.setLight(off).ok());
    EXPECT_EQ(onGpu.stats().faces, fresh->stats().faces);
    const auto expectStale = [](const auto& result) {
        ASSERT_FALSE(result.ok());
        EXPECT_NE(result.error().message().find("create the GPU passes again"), std::string::npos)
            << result.error().message();
    };
    expectStale(t.gpu->uploadLight());
    expectStale(t.gpu->iterate(1));
    expectStale(t.gpu->download());
    t.gpu.reset();
    auto gpu = RadianceCascadesGpu::create(*context, onGpu);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    expectOneThenThreePassesMatch(*fresh, onGpu, *gpu);
    // The picture on the device reads the new faces' table: the fresh build's picture, to the
    // GPU picture's float rounding (CascadesPictureGpu.*), looking at the window and the block.
    auto camera = Camera::create({9.0, 4.0, 13.0}, 180.0, -10.0, 70.0, 32, 18);
    ASSERT_TRUE(camera.ok());
    auto drawn = gpu->render(*camera);
    ASSERT_TRUE(drawn.ok()) << drawn.error().message();
    auto expected = fresh->render(*camera);
    ASSERT_TRUE(expected.ok());
    double difference = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < expected->size(); ++i) {
        difference += std::abs(drawn->data()[i] - expected->data()[i]);
        sum += expected->data()[i];
    }
    EXPECT_GT(sum, 0.0);
    EXPECT_LE(difference, 1e-4 * sum);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

}  // namespace
