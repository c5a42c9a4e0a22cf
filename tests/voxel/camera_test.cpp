// Tests for the voxel perspective camera: validation and primary rays.
#include "luxel/voxel/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace luxel::voxel {
namespace {

void expectNear(Vec3d a, Vec3d b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(VoxelCameraTest, RejectsBadInput) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(Camera::create({nan, 0, 0}, 0, 0, 60, 8, 8).ok());
    EXPECT_FALSE(Camera::create({0, 0, 0}, nan, 0, 60, 8, 8).ok());
    EXPECT_FALSE(Camera::create({0, 0, 0}, 0, 91, 60, 8, 8).ok());
    EXPECT_FALSE(Camera::create({0, 0, 0}, 0, 0, 0, 8, 8).ok());
    EXPECT_FALSE(Camera::create({0, 0, 0}, 0, 0, 180, 8, 8).ok());
    EXPECT_FALSE(Camera::create({0, 0, 0}, 0, 0, nan, 8, 8).ok());
    EXPECT_FALSE(Camera::create({0, 0, 0}, 0, 0, 60, 0, 8).ok());
    EXPECT_FALSE(Camera::create({0, 0, 0}, 0, 0, 60, 8, -1).ok());
    EXPECT_FALSE(Camera::lookAt({1, 2, 3}, {1, 2, 3}, 60, 8, 8).ok());
    const Result<Camera> bad = Camera::create({0, 0, 0}, 0, 0, 200, 8, 8);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("field of view"), std::string::npos);
    EXPECT_TRUE(Camera::create({0, 0, 0}, 0, 90, 60, 8, 8).ok());
}

TEST(VoxelCameraTest, YawPitchAxes) {
    Camera camera = Camera::create({1, 2, 3}, 0, 0, 90, 9, 9).value();
    expectNear(camera.forward(), {0, 0, 1});
    expectNear(camera.right(), {1, 0, 0});
    expectNear(camera.up(), {0, 1, 0});
    camera = Camera::create({1, 2, 3}, 90, 0, 90, 9, 9).value();
    expectNear(camera.forward(), {1, 0, 0});
    expectNear(camera.right(), {0, 0, -1});
    camera = Camera::create({1, 2, 3}, 0, 90, 90, 9, 9).value();
    expectNear(camera.forward(), {0, 1, 0});
    expectNear(camera.right(), {1, 0, 0});
}

TEST(VoxelCameraTest, PrimaryRaysThroughPixelCentres) {
    const Camera camera = Camera::create({1, 2, 3}, 0, 0, 90, 9, 5).value();
    // Odd sizes: the centre pixel looks straight ahead.
    Ray ray = camera.primaryRay(4, 2);
    EXPECT_EQ(ray.origin, (Vec3d{1, 2, 3}));
    expectNear(ray.direction, {0, 0, 1});
    // Top row looks up, left column looks left; rays are unit length.
    EXPECT_GT(camera.primaryRay(4, 0).direction.y, 0.0);
    EXPECT_LT(camera.primaryRay(0, 2).direction.x, 0.0);
    // The top edge of the image is at the half field of view (45 degrees here).
    ray = camera.rayAt(4.5, 0.0);
    EXPECT_NEAR(ray.direction.y, ray.direction.z, 1e-12);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 9; ++x)
            EXPECT_NEAR(length(camera.primaryRay(x, y).direction), 1.0, 1e-12);
    }
}

TEST(VoxelCameraTest, LookAtPointsAtTarget) {
    const Camera camera = Camera::lookAt({0, 10, 0}, {5, 0, 5}, 60, 11, 11).value();
    expectNear(camera.primaryRay(5, 5).direction, normalize(Vec3d{5, -10, 5}));
    const Camera down = Camera::lookAt({0, 10, 0}, {0, 0, 0}, 60, 11, 11).value();
    expectNear(down.forward(), {0, -1, 0});
    expectNear(down.right(), {1, 0, 0});
}

}  // namespace
}  // namespace luxel::voxel
