// render.samples in the pictures of the radiance cascades and of sky visibility
// (docs/algorithms/voxel-radiance-cascades.md §4.2): stratified rays inside each pixel at the ray
// caster's positions (shared/pixel_samples.h), averaged, so a pixel on an edge shows the part of
// it each side covers, as the path tracer's jittered pixels do. Checked against the coverage of
// an emitting square computed here from the camera's rays and a plane, independently of the
// voxel traversal; and the GPU picture against the CPU's on lavapipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "luxel/voxel/camera.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/radiance_cascades_gpu.h"
#include "luxel/voxel/sky_visibility.h"
#include "support/gpu_test_context.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr int kWidth = 40, kHeight = 30;
constexpr double kFront = 12.0;         // the emitting square's front face, z = 12
constexpr double kLow = 4, kHigh = 12;  // its extent in x and y

// Every voxel emits radiance 1 and reflects nothing, under a black sky: a pixel shows the part
// of it that sees the square.
ShadeOptions glowOnly() {
    return plainLight(0.0f, Rgb(1.0f), Rgb(0.0f));
}

VoxelWorld glowingSquare() {
    VoxelWorld world = makeWorld({16, 16, 16});
    for (int y = int(kLow); y < int(kHigh); ++y)
        for (int x = int(kLow); x < int(kLow) + 8; ++x) world.set(x, y, int(kFront), kWhite);
    world.refreshEmptySpace();
    return world;
}

// The camera off the square's axis so that its edges cross pixels at many fractions.
Camera edgeCamera() {
    return *Camera::lookAt({8.13, 8.37, 0.5}, {7.71, 7.94, 12.0}, 62.0, kWidth, kHeight);
}

// The fraction of pixel (px, py) whose rays meet the square's front face, on a 32 x 32 grid.
double coverage(const Camera& camera, int px, int py) {
    constexpr int n = 32;
    int inside = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const Ray r = camera.rayAt(px + (i + 0.5) / n, py + (j + 0.5) / n);
            const double t = (kFront - r.origin.z) / r.direction.z;
            const double x = r.origin.x + t * r.direction.x, y = r.origin.y + t * r.direction.y;
            inside += t > 0 && x > kLow && x < kHigh && y > kLow && y < kHigh;
        }
    return double(inside) / (n * n);
}

struct EdgeError {
    double largest = 0;  // the largest |pixel - coverage| over the edge pixels
    double mean = 0;     // their mean
    double power = 0;    // |sum of pixels - sum of coverage| / sum of coverage, whole image
    int edgePixels = 0;
};

EdgeError edgeError(const Image& picture, const Camera& camera) {
    EdgeError e;
    double sum = 0, covered = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double c = coverage(camera, x, y), v = picture.at(x, y, 1);
            sum += v;
            covered += c;
            if (c > 0.0 && c < 1.0) {
                e.largest = std::max(e.largest, std::abs(v - c));
                e.mean += std::abs(v - c);
                ++e.edgePixels;
            }
        }
    if (e.edgePixels > 0) e.mean /= e.edgePixels;
    e.power = covered > 0 ? std::abs(sum - covered) / covered : 1.0;
    return e;
}

Image cascadesPicture(int samples) {
    const VoxelWorld world = glowingSquare();
    ShadeOptions o = glowOnly();
    o.samplesPerPixel = samples;
    auto cascades = RadianceCascades::create(world, nullptr, o);
    EXPECT_TRUE(cascades.ok()) << cascades.error().message();
    if (!cascades.ok()) return {};
    cascades->solve();
    auto image = cascades->render(edgeCamera());
    EXPECT_TRUE(image.ok()) << image.error().message();
    return image.ok() ? std::move(*image) : Image{};
}

Image skyVisibilityPicture(int samples) {
    const VoxelWorld world = glowingSquare();
    ShadeOptions o = glowOnly();
    o.samplesPerPixel = samples;
    SkyVisibilityOptions options;
    options.rays = 4;
    auto image = renderSkyVisibility(world, edgeCamera(), o, options);
    EXPECT_TRUE(image.ok()) << image.error().message();
    return image.ok() ? std::move(image->radiance) : Image{};
}

void expectAntialiased(const Image& one, const Image& many, const char* name) {
    ASSERT_FALSE(one.empty());
    ASSERT_FALSE(many.empty());
    const EdgeError a = edgeError(one, edgeCamera()), b = edgeError(many, edgeCamera());
    std::printf(
        "%s: %d edge pixels; 1 sample: largest %.3f mean %.3f power %.4f; 64 samples: "
        "largest %.3f mean %.3f power %.4f\n",
        name, b.edgePixels, a.largest, a.mean, a.power, b.largest, b.mean, b.power);
    ASSERT_GE(b.edgePixels, 40);
    // One ray per pixel centre shows an edge pixel as all or nothing.
    EXPECT_GT(a.largest, 0.3) << name;
    EXPECT_GT(a.mean, 0.1) << name;
    // 8 x 8 jittered rays: an edge crosses at most 8 of 64 cells, half of each on average.
    EXPECT_LT(b.largest, 0.13) << name;
    EXPECT_LT(b.mean, 0.04) << name;
    EXPECT_LT(b.power, 0.01) << name;
}

TEST(PicturePixelSamples, CascadesEdgePixelsShowWhatTheyCover) {
    expectAntialiased(cascadesPicture(1), cascadesPicture(64), "radiance cascades");
}

TEST(PicturePixelSamples, SkyVisibilityEdgePixelsShowWhatTheyCover) {
    expectAntialiased(skyVisibilityPicture(1), skyVisibilityPicture(64), "sky visibility");
}

// The GPU picture takes the same rays at the same positions and draws the same random numbers
// on through a pixel's samples: the square lit by a sun with a disk (4 shadow rays a sample) and
// a sky, with 4 samples, agrees with the CPU to float rounding on lavapipe (the bounds of
// cascades_picture_gpu_test.cpp; the lighting passes on both agree to rounding too).
TEST(PicturePixelSamples, GpuCascadesPictureMatchesTheCpu) {
    gpu::Context* context = ::luxel::test::sharedGpuContext();
    if (!context) GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    const VoxelWorld world = glowingSquare();
    ShadeOptions o = plainLight(0.5f, Rgb(0.2f), Rgb(0.3f));
    o.sunIrradiance = Rgb(2.0f);
    o.sunDirection = {0.3f, 0.5f, -0.8f};
    o.sunAngularRadius = 0.05;
    const auto draw = [&](int samples, bool gpu) -> Image {
        o.samplesPerPixel = samples;
        auto cascades = RadianceCascades::create(world, nullptr, o);
        EXPECT_TRUE(cascades.ok()) << cascades.error().message();
        if (!cascades.ok()) return {};
        cascades->solve();
        if (!gpu) return *cascades->render(edgeCamera());
        auto onGpu = RadianceCascadesGpu::create(*context, *cascades);
        EXPECT_TRUE(onGpu.ok()) << onGpu.error().message();
        if (!onGpu.ok()) return {};
        EXPECT_TRUE(onGpu->solve().ok());
        auto picture = onGpu->render(edgeCamera());
        EXPECT_TRUE(picture.ok()) << picture.error().message();
        return picture.ok() ? std::move(*picture) : Image{};
    };
    const Image gpuPicture = draw(4, true), cpuPicture = draw(4, false), centres = draw(1, false);
    ASSERT_FALSE(gpuPicture.empty());
    double difference = 0, fromCentres = 0, total = 0;
    for (std::size_t i = 0; i < cpuPicture.size(); ++i) {
        difference += std::abs(cpuPicture.data()[i] - gpuPicture.data()[i]);
        fromCentres += std::abs(cpuPicture.data()[i] - centres.data()[i]);
        total += std::abs(cpuPicture.data()[i]);
    }
    ASSERT_GT(total, 0.0);
    std::printf("4 samples: GPU against CPU rel-L1 %.2e; 4 samples against 1: %.2e\n",
                difference / total, fromCentres / total);
    EXPECT_LE(difference / total, context->device().type == "cpu" ? 1e-6 : 2e-4);
    // The samples are not the pixel centres: the picture changes where edges cross pixels.
    EXPECT_GT(fromCentres / total, 1e-3);
    EXPECT_EQ(context->validationMessages(), 0) << context->lastValidationMessage();
}

}  // namespace
