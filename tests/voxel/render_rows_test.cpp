// render() casts a one-sample picture's camera rays a row at a time through castCameraRays when
// the camera is inside the world (docs/algorithms/voxel-traversal.md §4.6 "Picture path"): its
// pixels equal shadePixel's, which casts each ray on its own, to the bit, for both lighting models
// and every reflection mode.
#include <gtest/gtest.h>

#include <cstring>

#include "luxel/voxel/camera.h"
#include "luxel/voxel/render_image.h"
#include "terrain_with_blocks.h"

namespace luxel::voxel {
namespace {

void expectSamePixels(const VoxelWorld& world, const Camera& camera, const ShadeOptions& options) {
    const Image image = render(world, camera, options);
    const PreparedShading prepared(world, nullptr, options);
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Rgb c = shadePixel(world, camera, x, y, prepared.options(), nullptr);
            const float want[3] = {c.r, c.g, c.b};
            for (int k = 0; k < 3; ++k) {
                const float got = image.at(x, y, k);
                ASSERT_EQ(std::memcmp(&got, &want[k], sizeof(float)), 0)
                    << "pixel " << x << ", " << y << " channel " << k;
            }
        }
    }
}

TEST(VoxelRenderRows, CameraInsideMatchesPixelByPixel) {
    const VoxelWorld world = terrainWithBlocks({96, 64, 96}, 5, 40, 0.04, 30);
    const Camera cameras[] = {
        Camera::create({48.5, 50.25, 10.5}, 0, -12, 60, 83, 41).value(),  // inside, over the ground
        Camera::create({90.0, 60.0, 90.0}, 225, -20, 70, 64, 33).value(),  // on cell planes
        Camera::lookAt({-20, 80, -20}, {48, 20, 48}, 50, 40, 30).value(),  // outside
    };
    ShadeOptions classic;
    classic.maxReflections = 2;
    classic.reflectivity = 0.4f;
    ShadeOptions energy = classic;
    energy.reflectionMode = ShadeOptions::ReflectionMode::EnergyConserving;
    ShadeOptions physical;
    physical.lighting = ShadeOptions::Lighting::Physical;
    physical.maxReflections = 2;
    for (const Camera& camera : cameras) {
        for (const ShadeOptions& options : {classic, energy, physical}) {
            SCOPED_TRACE(testing::Message() << "camera at " << camera.position().x << ", "
                                            << camera.position().y << ", " << camera.position().z);
            expectSamePixels(world, camera, options);
        }
    }
}

}  // namespace
}  // namespace luxel::voxel
