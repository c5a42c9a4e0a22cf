// The radiance cascades' picture on a glossy floor beside a lamp
// (docs/algorithms/voxel-radiance-cascades.md §4.2): the camera surface's GGX rays met the small
// lamp now and then, each such pixel a sparkle; the near emitters' highlight is now light-sampled
// (their quarter points through the specular lobe, by the same near weight as their diffuse
// light), the GGX rays keeping only the far share. The floor in front of the lamp: a third of the
// sparkle, and the path tracer's mean (the highlight neither lost nor counted twice). Measured:
// largest pixel over its neighbours' median 5.2 with the near term alone, 1.33 with the far
// lamps' light samples taking the share it leaves (GGX rays alone 15.7); floor mean -0.8% of the
// path tracer's at 512 samples, the GGX rays alone +3.8% at 64 samples (the split sum's own
// bias on this floor, which the light-sampled share no longer has).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/surface_cast.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/room_pixels.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr Int3 kLamp{6, 1, 6};
constexpr Voxel kGlossy{255, 255, 255, alphaForSlot(1)};

// A closed 14-voxel grey room (walls one voxel thick, Lambertian) with a dark glossy dielectric
// floor and a one-voxel lamp on it, so that the floor in front of the lamp shows mostly the
// lamp's highlight.
struct GlossyLampRoom {
    VoxelWorld world = makeWorld({14, 14, 14});
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    GlossyLampRoom() {
        for (int z = 0; z < 14; ++z)
            for (int y = 0; y < 14; ++y)
                for (int x = 0; x < 14; ++x) {
                    if (y == 0) {
                        world.set(x, y, z, kGlossy);
                    } else if (x == 0 || z == 0 || x == 13 || y == 13 || z == 13) {
                        world.set(x, y, z, kWhite);
                    }
                }
        world.set(kLamp.x, kLamp.y, kLamp.z, Voxel{255, 255, 255, alphaForSlot(0)});
        world.refreshEmptySpace();
        EXPECT_TRUE(o.materials.setSlot(0, lampMaterial(Rgb(20.0f, 15.0f, 10.0f))).ok());
        EXPECT_TRUE(o.materials.setSlot(1, polishedFloor(0.1f)).ok());
    }
};

Camera view() {
    return *Camera::lookAt({6.5, 3.5, 1.5}, {6.5, 1.0, 5.5}, 60.0, 64, 48);
}

Image picture(const GlossyLampRoom& room, bool nearEmitters, int samples) {
    ShadeOptions o = room.o;
    o.samplesPerPixel = samples;
    CascadeOptions options;
    options.nearEmitters = nearEmitters;
    // Off: the GGX rays alone, the far lamps' light samples (§4.2) off too.
    options.glossyEmitters = nearEmitters;
    auto cascades = RadianceCascades::create(room.world, nullptr, o, options);
    EXPECT_TRUE(cascades.ok()) << cascades.error().message();
    cascades->solve();
    auto image = cascades->render(view());
    EXPECT_TRUE(image.ok()) << image.error().message();
    return std::move(*image);
}

// The floor pixels in front of the lamp, within 2.5 voxels of its foot, whose eight neighbours
// meet the floor too (away from the lamp's silhouette).
std::vector<std::pair<int, int>> floorBeforeTheLamp(const GlossyLampRoom& room) {
    const Camera camera = view();
    std::vector<std::pair<int, int>> pixels;
    for (int y = 1; y + 1 < camera.height(); ++y)
        for (int x = 1; x + 1 < camera.width(); ++x) {
            bool floor = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const Hit h = hitAt(room, camera, x + dx, y + dy);
                    floor &= h.hit && h.voxel.y == 0 && h.normal == Int3{0, 1, 0};
                }
            if (!floor) continue;
            const Hit h = hitAt(room, camera, x, y);
            const double dx = std::max({kLamp.x - h.point.x, 0.0, h.point.x - kLamp.x - 1.0});
            const double dz = kLamp.z - h.point.z;
            if (dz >= 0.0 && std::sqrt(dx * dx + dz * dz) < 2.5) pixels.emplace_back(x, y);
        }
    return pixels;
}

TEST(CascadesNearHighlight, NoSparklesOnAGlossyFloorBesideALamp) {
    const GlossyLampRoom room;
    const auto pixels = floorBeforeTheLamp(room);
    ASSERT_GT(pixels.size(), 100u);
    const double now = sparkles(picture(room, true, 1), pixels, 0.0).largest;
    const double before = sparkles(picture(room, false, 1), pixels, 0.0).largest;
    std::printf(
        "%zu floor pixels: largest pixel / median of its neighbours %.2f (GGX rays "
        "alone %.2f)\n",
        pixels.size(), now, before);
    EXPECT_LT(now, 7.0);
    EXPECT_GT(before, 2.5 * now);
}

TEST(CascadesNearHighlight, TheHighlightIsNeitherLostNorCountedTwice) {
    const GlossyLampRoom room;
    const auto pixels = floorBeforeTheLamp(room);
    ASSERT_GT(pixels.size(), 100u);
    PathTraceOptions p;
    p.samplesPerPixel = 512;
    p.maxBounces = 64;
    auto truth = pathTrace(room.world, view(), room.o, p);
    ASSERT_TRUE(truth.ok()) << truth.error().message();
    const double reference = regionMean(truth->radiance, pixels);
    const double now = regionMean(picture(room, true, 16), pixels);
    const double before = regionMean(picture(room, false, 64), pixels);
    std::printf(
        "floor mean: path %.4f, light-sampled highlight %.4f (%+.1f%%), GGX rays alone "
        "at 64 samples %.4f (%+.1f%%), the two %+.1f%% apart\n",
        reference, now, 100 * (now / reference - 1), before, 100 * (before / reference - 1),
        100 * (now / before - 1));
    // Counted twice or lost, the lamp's highlight moves this mean by far more than these bounds.
    EXPECT_NEAR(now / reference, 1.0, 0.03);
    EXPECT_LT(std::abs(now / reference - 1.0), std::abs(before / reference - 1.0));
}

}  // namespace
