// Renders from awkward places give sensible, finite images: a camera inside solid rock, one far
// outside the world, one looking straight down, and a world with no solid voxel at all.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/voxel/camera.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kRock{120, 110, 100, 255};

bool allFinite(const Image& image) {
    for (std::size_t i = 0; i < image.size(); ++i)
        if (!std::isfinite(image.data()[i])) return false;
    return true;
}

VoxelWorld rockSlab() {
    VoxelWorld world = VoxelWorld::create({32, 32, 32}, 8).value();
    addBox(world, {0, 0, 0}, {32, 16, 32}, kRock);
    return world;
}

TEST(VoxelRenderEdgeCases, CameraInsideSolidSeesItsOwnVoxelEverywhere) {
    const VoxelWorld world = rockSlab();
    const Camera camera = Camera::create({16.5, 8.5, 16.5}, 30, -10, 70, 24, 16).value();
    ShadeOptions options;
    options.maxReflections = 3;
    const Image image = render(world, camera, options);
    ASSERT_TRUE(allFinite(image));
    // Every ray starts inside the rock: hit at t = 0 with no face, so no reflection and no shadow
    // ray; the whole image is that voxel's colour under the no-normal face factor.
    const Rgb first = image.rgb(0, 0);
    EXPECT_GT(first.r, 0.0f);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Rgb c = image.rgb(x, y);
            EXPECT_NEAR(c.r, first.r, 0.2f * first.r) << x << " " << y;
        }
    }
}

TEST(VoxelRenderEdgeCases, FarOutsideCameraSeesTheWorldSmallAndSkyAround) {
    const VoxelWorld world = rockSlab();
    const Camera camera = Camera::lookAt({16, 40, -5000}, {16, 8, 16}, 2, 32, 32).value();
    const Image image = render(world, camera, {});
    ASSERT_TRUE(allFinite(image));
    // Corner rays miss the world and see the sky along their own direction.
    const Rgb sky = skyColor(camera.primaryRay(0, 0).direction, {});
    EXPECT_NEAR(image.rgb(0, 0).b, sky.b, 1e-6f);
    // The slab (32 x 16 voxels, 5000 away, in a 2 degree view) covers a few pixels at the centre.
    int rockPixels = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Rgb ownSky = skyColor(camera.primaryRay(x, y).direction, {});
            rockPixels += std::abs(image.rgb(x, y).b - ownSky.b) > 0.05f;
        }
    }
    EXPECT_GE(rockPixels, 4);
    EXPECT_LE(rockPixels, 40);
}

TEST(VoxelRenderEdgeCases, EmptyWorldIsAllSkyAndStraightDownIsFine) {
    const VoxelWorld empty = VoxelWorld::create({16, 16, 16}, 8).value();
    const Camera down = Camera::create({8, 30, 8}, 0, -90, 60, 8, 8).value();
    const Image image = render(empty, down, {});
    ASSERT_TRUE(allFinite(image));
    const Rgb horizon = ShadeOptions{}.skyHorizon;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) EXPECT_NEAR(image.rgb(x, y).g, horizon.g, 1e-6f);
    }
    const Image onRock = render(rockSlab(), down, {});
    ASSERT_TRUE(allFinite(onRock));
    EXPECT_LT(onRock.rgb(4, 4).b, horizon.b);  // the rock top, lit from above
}

}  // namespace
}  // namespace luxel::voxel
