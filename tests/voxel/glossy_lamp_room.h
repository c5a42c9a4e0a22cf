// A closed room whose walls and ceiling are glossy, lit by one small lamp on its floor far from
// them (the far-lamp tests of docs/algorithms/voxel-radiance-cascades.md §4.2, "Far lamps in the
// glossy lobe"): the wall the camera faces shows the lamp's reflection from 7 voxels and more
// away, well past the near term's 4.
#pragma once

#include <utility>
#include <vector>

#include "luxel/voxel/camera.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/room_pixels.h"

namespace luxel::voxel::test {

// An 18-voxel room (walls one voxel thick): a Lambertian floor of `albedo`, dark glossy
// dielectric walls and ceiling (polishedFloor(albedo / 5): roughness 0.4), a one-voxel lamp at
// its centre. Albedo 0 leaves the lamp's glossy reflections alone.
struct GlossyWallsRoom {
    static constexpr Int3 kLamp{8, 1, 8};
    VoxelWorld world = makeWorld({18, 18, 18});
    ShadeOptions o;
    explicit GlossyWallsRoom(float albedo = 0.5f) : o(plainLight(albedo, Rgb(0.0f), Rgb(0.0f))) {
        const Voxel glossy{255, 255, 255, alphaForSlot(1)};
        for (int z = 0; z < 18; ++z)
            for (int y = 0; y < 18; ++y)
                for (int x = 0; x < 18; ++x) {
                    if (y == 0) {
                        world.set(x, y, z, kWhite);
                    } else if (x == 0 || z == 0 || x == 17 || y == 17 || z == 17) {
                        world.set(x, y, z, glossy);
                    }
                }
        world.set(kLamp.x, kLamp.y, kLamp.z, Voxel{255, 255, 255, alphaForSlot(0)});
        world.refreshEmptySpace();
        EXPECT_TRUE(o.materials.setSlot(0, lampMaterial(Rgb(20.0f, 15.0f, 10.0f))).ok());
        EXPECT_TRUE(o.materials.setSlot(1, polishedFloor(albedo / 5.0f)).ok());
    }
};

// From beside the lamp towards the far wall (z = 17), where its reflection lies.
inline Camera farWallView(int width = 64, int height = 48) {
    return *Camera::lookAt({8.5, 3.0, 3.5}, {8.5, 3.5, 17.0}, 60.0, width, height);
}

// The pixels whose centre rays, and their eight neighbours', meet the far wall's face.
inline std::vector<std::pair<int, int>> farWallPixels(const GlossyWallsRoom& room,
                                                      const Camera& camera) {
    std::vector<std::pair<int, int>> pixels;
    for (int y = 1; y + 1 < camera.height(); ++y)
        for (int x = 1; x + 1 < camera.width(); ++x) {
            bool wall = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const Hit h = hitAt(room, camera, x + dx, y + dy);
                    wall &= h.hit && h.voxel.z == 17 && h.normal == Int3{0, 0, -1};
                }
            if (wall) pixels.emplace_back(x, y);
        }
    return pixels;
}

}  // namespace luxel::voxel::test
