// The pixel loop: stratified sample positions, one sample at the pixel centre, primary cones,
// determinism across thread counts.
#include <gtest/gtest.h>

#include <set>

#include "gpu/shaders/shared/pixel_samples.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/render_image.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

// Every n: offsets in [0, 1)^2, one per column stratum of width 1/n (N-rooks) and one per row
// stratum; square n: one per cell of the g x g grid.
TEST(PixelSamples, StratifiedAndDeterministic) {
    for (int n = 2; n <= 64; ++n) {
        for (std::uint32_t px : {0u, 7u, 1000u}) {
            std::set<int> columns, rows, cells;
            const int g = int(std::lround(std::sqrt(double(n))));
            for (int k = 0; k < n; ++k) {
                const shared::vec2 o = shared::pixelSampleOffset(px, 3u, k, n);
                ASSERT_GE(o.x, 0.0f);
                ASSERT_LT(o.x, 1.0f);
                ASSERT_GE(o.y, 0.0f);
                ASSERT_LT(o.y, 1.0f);
                const shared::vec2 again = shared::pixelSampleOffset(px, 3u, k, n);
                EXPECT_EQ(o.x, again.x);
                EXPECT_EQ(o.y, again.y);
                if (g * g == n) {
                    cells.insert(int(o.y * g) * g + int(o.x * g));
                } else {
                    columns.insert(int(o.x * n));
                    rows.insert(int(o.y * n));
                }
            }
            if (g * g == n) {
                EXPECT_EQ(int(cells.size()), n) << n;
            } else {
                EXPECT_EQ(int(columns.size()), n) << n;
                EXPECT_EQ(int(rows.size()), n) << n;
            }
        }
    }
    const shared::vec2 centre = shared::pixelSampleOffset(5u, 6u, 0, 1);
    EXPECT_EQ(centre.x, 0.5f);
    EXPECT_EQ(centre.y, 0.5f);
    // Different pixels get different jitter.
    EXPECT_NE(shared::pixelSampleOffset(1u, 0u, 0, 4).x, shared::pixelSampleOffset(2u, 0u, 0, 4).x);
}

TEST(RenderImage, OneSampleIsThePixelCentreRay) {
    VoxelWorld world = VoxelWorld::create({16, 16, 16}, 8).value();
    addBox(world, {0, 0, 0}, {16, 3, 16}, Voxel{90, 160, 70, 255});
    addBox(world, {5, 3, 9}, {9, 9, 12}, Voxel{200, 60, 40, 255});
    const Camera camera = Camera::lookAt({2.5, 8.2, 1.3}, {8, 3, 10}, 60, 20, 14).value();
    ShadeOptions options;
    const Image image = render(world, camera, options);
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Rgb c = shadeRay(world, camera.primaryRay(x, y), options);
            EXPECT_EQ(image.rgb(x, y).r, c.r);
            EXPECT_EQ(image.rgb(x, y).g, c.g);
        }
    }
    // With 9 samples, the same image whatever the thread count, and a pixel's value is the mean
    // of its samples.
    options.samplesPerPixel = 9;
    const Image one = [&] {
        ThreadLimit limit(1);
        return render(world, camera, options);
    }();
    const Image many = render(world, camera, options);
    for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one.data()[i], many.data()[i]);
    Rgb sum;
    RayCone cone = primaryCone(camera);
    cone.spread /= 3.0;
    for (int k = 0; k < 9; ++k) {
        const shared::vec2 o = shared::pixelSampleOffset(4u, 5u, k, 9);
        sum += shadeRay(world, camera.rayAt(4 + double(o.x), 5 + double(o.y)), cone, options);
    }
    EXPECT_NEAR(one.rgb(4, 5).r, sum.r / 9, 1e-6f);
}

TEST(RenderImage, PrimaryConeSpreadsByOnePixel) {
    const Camera camera = Camera::create({0, 0, 0}, 0, 0, 90, 100, 50).value();
    const RayCone cone = primaryCone(camera);
    EXPECT_EQ(cone.width, 0.0);
    // Adjacent pixel centres at the image centre are 2 tan(45 deg) / 50 apart at distance 1.
    EXPECT_NEAR(cone.spread, 2.0 / 50, 1e-12);
    const Ray a = camera.rayAt(50, 25), b = camera.rayAt(51, 25);
    EXPECT_NEAR(length(a.direction - b.direction), cone.spread, 1e-3);
}

}  // namespace
}  // namespace luxel::voxel
