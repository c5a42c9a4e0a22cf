// Rough lobes follow no face (docs/algorithms/voxel-radiance-cascades.md §4.2): the GGX rays of a
// rough camera surface take a polished mirror as a Lambertian face, as they take a metal too
// rough to be followed. A rough floor before a metal wall draws the same picture to the bit
// whether the wall is a mirror (followed by delta lobes) or rough metal (never followed), where
// the floor's lobe is rough; a polished floor's GGX rays still follow the mirror and see the
// difference, as the camera does looking at the wall itself.
#include <gtest/gtest.h>

#include "luxel/voxel/radiance_cascades.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/solver_surface.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

// A 24x12x24 floor (texture slot 1) in sunlight under a sky, a metal wall (slot 0) 8 high along
// z = 20, the camera looking down at the floor before the wall from the side away from it.
struct FloorBeforeAWall {
    VoxelWorld world = makeWorld({24, 12, 24});
    FloorBeforeAWall() {
        for (int z = 0; z < 24; ++z)
            for (int x = 0; x < 24; ++x) world.set(x, 0, z, Voxel{200, 190, 180, 2});
        for (int y = 1; y < 9; ++y)
            for (int x = 2; x < 22; ++x) world.set(x, y, 20, Voxel{230, 230, 235, 1});
        world.refreshEmptySpace();
    }
    // The picture with the wall's metal of `wallRoughness` and the floor of `floorRoughness`.
    Image draw(float wallRoughness, float floorRoughness, const Camera& camera) const {
        ShadeOptions o = plainLight(0.6f, Rgb(0.0f), Rgb(0.35f, 0.5f, 0.85f));
        o.sunIrradiance = Rgb(3.0f);
        o.sunDirection = {0.3f, 0.8f, -0.5f};
        o.sunAngularRadius = 0.03;
        EXPECT_TRUE(o.materials.setSlot(0, metal(wallRoughness, Rgb(0.9f))).ok());
        Material floor;
        floor.name = "floor";
        floor.albedo = Rgb(0.6f);
        floor.ior = 1.5f;
        floor.roughness = floorRoughness;
        EXPECT_TRUE(o.materials.setSlot(1, floor).ok());
        auto cascades = RadianceCascades::create(world, nullptr, o, CascadeOptions{});
        EXPECT_TRUE(cascades.ok());
        cascades->solve();
        auto image = cascades->render(camera);
        EXPECT_TRUE(image.ok());
        return std::move(*image);
    }
};

// Pixels that differ between two pictures of one size.
int differing(const Image& a, const Image& b) {
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            bool same = true;
            for (int c = 0; c < 3; ++c) same = same && a.at(x, y, c) == b.at(x, y, c);
            count += !same;
        }
    return count;
}

TEST(CascadesRoughLobe, ARoughFloorsRaysTakeAMirrorAsTheyTakeRoughMetal) {
    const FloorBeforeAWall scene;
    ASSERT_LT(0.02f, kSolverFollowRoughness);
    ASSERT_GT(0.3f, kSolverFollowRoughness);
    // Down at the floor in front of the wall, the wall itself out of view.
    const Camera floor = *Camera::lookAt({12.0, 8.0, 4.0}, {12.0, 0.0, 9.0}, 50.0, 48, 32);
    const Image mirrorWall = scene.draw(0.02f, 0.8f, floor);
    const Image roughWall = scene.draw(0.3f, 0.8f, floor);
    EXPECT_EQ(differing(mirrorWall, roughWall), 0);
    // A polished floor's GGX rays follow the mirror (a sharp lobe): the wall's roughness shows.
    const Image polishedMirror = scene.draw(0.02f, 0.05f, floor);
    const Image polishedRough = scene.draw(0.3f, 0.05f, floor);
    EXPECT_GT(differing(polishedMirror, polishedRough), 48 * 32 / 10);
    // And so does the camera's own view of the wall.
    const Camera wall = *Camera::lookAt({12.0, 5.0, 8.0}, {12.0, 4.0, 20.0}, 50.0, 48, 32);
    EXPECT_GT(differing(scene.draw(0.02f, 0.8f, wall), scene.draw(0.3f, 0.8f, wall)), 48 * 32 / 2);
}

}  // namespace
