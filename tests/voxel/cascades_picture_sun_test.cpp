// The voxel radiance cascades' picture counts the sun's highlight once
// (docs/algorithms/voxel-radiance-cascades.md §4.2): a glossy floor's sun rays pass glass along
// the straight line and bring the highlight, so a GGX reflection ray that passes the same glass
// into the sun's disk must not show the disk again. Under a clear pane the floor can only be
// darker than under the open sky.
#include <gtest/gtest.h>

#include "luxel/voxel/camera.h"
#include "luxel/voxel/radiance_cascades.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

// A glossy floor (GGX, roughness 0.3, ior 1.5) under a clear pane at y = 5 covering the world
// (or under nothing), a dim sky and a wide sun (0.2 rad) where the floor mirrors it towards the
// camera.
double meanPicture(bool pane) {
    VoxelWorld world = pane ? paneOverAFloor() : makeWorld({24, 8, 24});
    if (!pane) {
        for (int z = 0; z < 24; ++z)
            for (int x = 0; x < 24; ++x) world.set(x, 0, z, kWhite);
        world.refreshEmptySpace();
    }
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.2f));
    Material floor;
    floor.name = "floor";
    floor.albedo = Rgb(0.5f);
    floor.roughness = 0.3f;
    floor.ior = 1.5f;
    EXPECT_TRUE(o.materials.setPlain(floor).ok());
    EXPECT_TRUE(o.materials.setSlot(0, glass()).ok());
    o.sunIrradiance = Rgb(2.0f);
    o.sunDirection = {8.0f, 3.5f, 8.0f};
    o.sunAngularRadius = 0.2;
    auto cascades = RadianceCascades::create(world, nullptr, o);
    EXPECT_TRUE(cascades.ok()) << cascades.error().message();
    if (!cascades.ok()) return 0.0;
    cascades->solve();
    const Camera camera = *Camera::lookAt({4.0, 3.5, 4.0}, {12.0, 0.0, 12.0}, 50.0, 32, 24);
    auto image = cascades->render(camera);
    EXPECT_TRUE(image.ok());
    if (!image.ok()) return 0.0;
    double sum = 0.0;
    for (int y = 0; y < image->height(); ++y)
        for (int x = 0; x < image->width(); ++x) sum += image->at(x, y, 1);
    return sum / (image->width() * image->height());
}

TEST(CascadesPictureSun, HighlightThroughAPaneIsCountedOnce) {
    const double open = meanPicture(false), covered = meanPicture(true);
    ASSERT_GT(open, 0.0);
    // The pane takes away at least its Fresnel reflections of sun and sky, and adds only the
    // floor's light it reflects back; counting the disk behind it again made it brighter.
    EXPECT_LT(covered, open);
    EXPECT_GT(covered, 0.3 * open);
}

}  // namespace
