// The radiance cascades' adaptive pass on the GPU (RadianceCascadesGpu::render, a second
// dispatch of cascades_picture.comp.glsl over the pixels src/voxel/cascades/adaptive_samples.h
// picks on the downloaded first pass) against the CPU's (RadianceCascades::render), from the same
// faces' irradiance: a one-voxel lamp in a dark room, whose silhouette the pass refines. Both
// refine the same pixels with the same rays and random numbers, so on lavapipe the pictures agree
// to float rounding as the plain picture's do (cascades_picture_gpu_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/radiance_cascades_gpu.h"
#include "support/gpu_test_context.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

// A closed 14-voxel grey room (walls one voxel thick) lit by one bright voxel in the air.
VoxelWorld lampRoom() {
    auto created = VoxelWorld::create({14, 14, 14}, 8);
    EXPECT_TRUE(created.ok());
    VoxelWorld world = std::move(*created);
    for (int z = 0; z < 14; ++z)
        for (int y = 0; y < 14; ++y)
            for (int x = 0; x < 14; ++x) {
                if (x == 0 || y == 0 || z == 0 || x == 13 || y == 13 || z == 13) {
                    world.set(x, y, z, Voxel{200, 200, 200, 255});
                }
            }
    world.set(7, 5, 8, Voxel{255, 255, 255, 1});  // texture slot 0: the lamp
    world.refreshEmptySpace();
    return world;
}

ShadeOptions lampLight() {
    ShadeOptions o;
    o.textures = false;
    o.skyHorizon = o.skyTop = Rgb(0.0f);
    o.sunIrradiance = Rgb(0.0f);
    Material plain;
    plain.name = "plain";
    plain.albedo = Rgb(0.5f);
    EXPECT_TRUE(o.materials.setPlain(plain).ok());
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = Rgb(40.0f, 30.0f, 20.0f);
    EXPECT_TRUE(o.materials.setSlot(0, lamp).ok());
    o.samplesPerPixel = 1;
    o.adaptiveSamples = 16;
    return o;
}

double relativeL1(const Image& a, const Image& b) {
    double difference = 0, total = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        difference += std::abs(double(a.data()[i]) - b.data()[i]);
        total += std::abs(double(a.data()[i]));
    }
    return total > 0 ? difference / total : difference;
}

TEST(CascadesAdaptiveGpu, RefinedPictureMatchesTheCpu) {
    LUXEL_REQUIRE_GPU(context);
    const VoxelWorld world = lampRoom();
    const ShadeOptions o = lampLight();
    CascadeOptions options;
    options.bounces = 4;
    auto cascades = RadianceCascades::create(world, nullptr, o, options);
    ASSERT_TRUE(cascades.ok()) << cascades.error().message();
    auto gpu = RadianceCascadesGpu::create(*context, *cascades);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    ASSERT_TRUE(gpu->solve().ok());
    ASSERT_TRUE(gpu->download().ok());  // both pictures from the same irradiance
    // Small, for lavapipe: the lamp about 3 pixels wide.
    const Camera camera = *Camera::lookAt({3.31, 7.83, 2.17}, {7.46, 5.41, 8.52}, 60.0, 48, 36);
    int gpuRefined = -1, cpuRefined = -1;
    double ms = 0;
    auto onGpu = gpu->render(camera, &ms, 0, &gpuRefined);
    ASSERT_TRUE(onGpu.ok()) << onGpu.error().message();
    auto onCpu = cascades->render(camera, &cpuRefined);
    ASSERT_TRUE(onCpu.ok()) << onCpu.error().message();
    // The first pass alone, on the GPU: what the adaptive pass changed.
    cascades->setPictureAdaptiveSamples(0, o.adaptiveContrast);
    int plainRefined = -1;
    auto plain = gpu->render(camera, nullptr, 0, &plainRefined);
    ASSERT_TRUE(plain.ok()) << plain.error().message();
    const double parity = relativeL1(*onCpu, *onGpu), changed = relativeL1(*onGpu, *plain);
    std::printf(
        "GPU against CPU rel-L1 %.2e, %d and %d pixels refined; the pass changed %.2e; "
        "%.2f ms\n",
        parity, gpuRefined, cpuRefined, changed, ms);
    EXPECT_EQ(plainRefined, 0);
    EXPECT_GT(cpuRefined, 10);
    const bool lavapipe = context->device().type == "cpu";
    // A hardware driver's rounding may move a pixel across the contrast threshold.
    if (lavapipe) {
        EXPECT_EQ(gpuRefined, cpuRefined);
    } else {
        EXPECT_NEAR(gpuRefined, cpuRefined, 2);
    }
    EXPECT_LE(parity, lavapipe ? 1e-6 : 1e-3);
    EXPECT_GT(changed, 1e-3);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

}  // namespace
