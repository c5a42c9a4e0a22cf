// A .vox opened as a scene: the camera frames what is solid (every solid voxel inside the image,
// the model centred and filling it), whatever empty space the models' boxes hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "luxel/voxel/vox_scene.h"
#include "support/vox_writer.h"

namespace luxel::voxel {
namespace {

namespace vw = luxel::test::vox;

TEST(VoxScene, FramingCameraSeesEverySolidVoxelCentredAndLarge) {
    // A 40^3 model box holding a 9 x 5 x 3 block near one corner (vox axes).
    std::vector<vw::Voxel4> voxels;
    for (std::uint8_t x = 2; x < 11; ++x)
        for (std::uint8_t y = 30; y < 35; ++y)
            for (std::uint8_t z = 0; z < 3; ++z) voxels.push_back({x, y, z, 1});
    Result<VoxelScene> scene =
        voxSceneFromBytes(vw::file(vw::model(40, 40, 40, voxels)), "block.vox", {160, 90});
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const Camera& camera = scene->camera;
    const double tanY = std::tan(camera.fovYDegrees() * M_PI / 360.0);
    const double tanX = tanY * 160.0 / 90.0;
    double uLo = 1e9, uHi = -1e9, vLo = 1e9, vHi = -1e9;
    const Int3 s = scene->world.size();
    for (int z = 0; z < s.z; ++z) {
        for (int y = 0; y < s.y; ++y) {
            for (int x = 0; x < s.x; ++x) {
                if (!scene->world.solid(x, y, z)) continue;
                for (int corner = 0; corner < 8; ++corner) {
                    const Vec3d p{x + double(corner & 1), y + double(corner >> 1 & 1),
                                  z + double(corner >> 2 & 1)};
                    const Vec3d d = p - camera.position();
                    const auto dot = [](Vec3d a, Vec3d b) {
                        return a.x * b.x + a.y * b.y + a.z * b.z;
                    };
                    const double depth = dot(d, camera.forward());
                    ASSERT_GT(depth, 0.0);
                    const double u = dot(d, camera.right()) / depth / tanX;
                    const double v = dot(d, camera.up()) / depth / tanY;
                    uLo = std::min(uLo, u), uHi = std::max(uHi, u);
                    vLo = std::min(vLo, v), vHi = std::max(vHi, v);
                }
            }
        }
    }
    EXPECT_GE(uLo, -1.0);
    EXPECT_LE(uHi, 1.0);
    EXPECT_GE(vLo, -1.0);
    EXPECT_LE(vHi, 1.0);
    // Centred, and filling the image along its tighter axis up to the margin.
    EXPECT_NEAR(uLo + uHi, 0.0, 0.02);
    EXPECT_NEAR(vLo + vHi, 0.0, 0.02);
    EXPECT_GT(std::max(uHi - uLo, vHi - vLo), 1.7);  // 85% of the image, less the margin
    EXPECT_GT(camera.position().y, 3.0);             // from above the block
}

}  // namespace
}  // namespace luxel::voxel
