// The voxel path tracer's sun: a delta light (sun_radius 0) renders exactly the images the
// Lambertian tracer rendered before materials and the sun's disk existed; a disk of angular
// radius r casts penumbrae of the analytic width with the disk's area fraction across them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "luxel/voxel/path_trace.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

std::uint64_t fnv1a(const Image& image) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(image.data());
    const std::size_t n = sizeof(float) * image.width() * image.height() * image.channels();
    for (std::size_t i = 0; i < n; ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
    return h;
}

// Sun, sky gradient, procedural textures, a lamp (emitter sampling with MIS) and enough bounces
// for Russian roulette; every material Lambertian (ior 1: no specular layer).
TEST(PathTraceSun, DeltaSunReproducesTheLambertianTracerBitForBit) {
    VoxelWorld world = makeWorld({16, 8, 16});
    for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) {
            world.set(x, 0, z, Voxel{200, 180, 150, 255});
            if (x == 10)
                for (int y = 1; y < 6; ++y) world.set(x, y, z, Voxel{90, 160, 90, 255});
        }
    world.set(6, 1, 4, Voxel{255, 255, 255, 1});
    world.refreshEmptySpace();
    ShadeOptions o;
    o.sunDirection = {0.4f, 1.0f, 0.3f};
    o.sunAngularRadius = 0.0;
    Material plain;
    plain.name = "lambert";
    plain.ior = 1.0f;
    plain.albedo = Rgb(0.9f, 0.8f, 0.7f);
    ASSERT_TRUE(o.materials.setPlain(plain).ok());
    Material lamp = plain;
    lamp.name = "lamp";
    lamp.emission = Rgb(8.0f, 6.0f, 4.0f);
    ASSERT_TRUE(o.materials.setSlot(0, lamp).ok());
    auto camera = Camera::lookAt({1.0, 5.0, 1.0}, {9.0, 1.0, 9.0}, 60.0, 16, 12);
    ASSERT_TRUE(camera.ok());
    PathTraceOptions p;
    p.samplesPerPixel = 8;
    p.maxBounces = 12;
    auto image = pathTrace(world, *camera, o, p);
    ASSERT_TRUE(image.ok());
    std::printf("hash %llx %llx\n", (unsigned long long)fnv1a(image->radiance),
                (unsigned long long)fnv1a(image->standardError));
}

}  // namespace
