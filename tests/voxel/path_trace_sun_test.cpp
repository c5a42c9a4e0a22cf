// The voxel path tracer's sun: a delta light (sun_radius 0) renders exactly the images the
// Lambertian tracer rendered before materials and the sun's disk existed; a disk of angular
// radius r casts penumbrae of the analytic width with the disk's area fraction across them, in
// the path tracer and in the sky visibility renderer alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/sky_visibility.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr double kPi = 3.14159265358979323846;

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
    // The hashes of the images the tracer rendered before it had materials or a sun disk
    // (measured on that code): the same numbers in the same order give the same bits.
    EXPECT_EQ(fnv1a(image->radiance), 0xfa4c4cf8781f4759ull);
    EXPECT_EQ(fnv1a(image->standardError), 0x5e632b072fd3df5eull);
}

// A floor (top at y = 1) under a roof (y in [11, 12), x < 20, all z), the sun straight up with
// radius r = 5 degrees, the sky black, the floor Lambertian. Under the roof the occluding edge is
// its lower one (h = 10 above the floor), beside it its upper one (h = 11: rays passing the lower
// edge still meet the roof's side). A floor point at x sees the part of the disk beyond that
// edge: with s = (20 - x) / (h tan r), the disk's area fraction beyond a chord at s,
// (acos s - s sqrt(1 - s^2)) / pi: 0 for s >= 1, 1 for s <= -1, so the penumbra runs from
// 20 - 10 tan r to 20 + 11 tan r.
struct PenumbraScene {
    VoxelWorld world = makeWorld({40, 14, 8});
    ShadeOptions o = plainLight(0.8f, Rgb(0.0f), Rgb(0.0f));
    static constexpr double kEdge = 20.0;
    double halfWidth = 0.0;  // tan r x the lower edge's height, 10
    PenumbraScene() {
        for (int z = 0; z < 8; ++z)
            for (int x = 0; x < 40; ++x) {
                world.set(x, 0, z, kWhite);
                if (x < 20) world.set(x, 11, z, kWhite);
            }
        world.refreshEmptySpace();
        o.sunIrradiance = Rgb(3.0f);
        o.sunDirection = {0.0f, 1.0f, 0.0f};
        o.sunAngularRadius = 5.0 * kPi / 180.0;
        halfWidth = 10.0 * std::tan(o.sunAngularRadius);
    }
    // The floor's expected radiance at x: albedo / pi x E x the visible fraction.
    double expected(double x) const {
        const double h = x < kEdge ? 10.0 : 11.0;
        const double s = std::clamp((kEdge - x) / (h * std::tan(o.sunAngularRadius)), -1.0, 1.0);
        return 0.8 / kPi * 3.0 * (std::acos(s) - s * std::sqrt(1.0 - s * s)) / kPi;
    }
    double pathMean(double x, int samples, double* standardError = nullptr) const {
        PathTraceOptions p;
        p.maxBounces = 1;  // direct light: the sun's disk by both strategies
        double sum = 0, squares = 0;
        for (int k = 0; k < samples; ++k) {
            PathRng rng(7, std::uint64_t(x * 1000), std::uint64_t(k));
            const double l =
                tracePath(world, nullptr, {{x, 1.5, 4.3}, {0.0, -1.0, 0.0}}, o, p, rng).r;
            sum += l, squares += l * l;
        }
        const double mean = sum / samples;
        if (standardError) {
            *standardError =
                std::sqrt(std::max(0.0, squares / samples - mean * mean) / (samples - 1));
        }
        return mean;
    }
};

TEST(PathTraceSun, DiskCastsThePenumbraOfItsAreaFraction) {
    const PenumbraScene s;
    EXPECT_NEAR(s.halfWidth, 0.875, 1e-3);
    // Across the penumbra the radiance follows the disk's area fraction (nearly linear in x in
    // the middle); the 1% allows for cos over the disk and the tangent's distortion at 5 deg.
    const double full = s.expected(40.0);
    for (int i = -6; i <= 7; ++i) {
        const double x = PenumbraScene::kEdge + i * 0.2 * s.halfWidth;
        double se = 0.0;
        const double mean = s.pathMean(x, 4000, &se);
        EXPECT_NEAR(mean, s.expected(x), 4.0 * se + 0.01 * full) << "x " << x;
    }
    // The umbra ends where the analytic width says: the first x with any light lies within
    // 0.1 voxel of edge - h tan r (exact zeros before it: every shadow ray is blocked).
    double firstLit = 0.0;
    for (double x = PenumbraScene::kEdge - 1.3 * s.halfWidth; x < PenumbraScene::kEdge; x += 0.01) {
        if (s.pathMean(x, 256) > 0.0) {
            firstLit = x;
            break;
        }
    }
    EXPECT_NEAR(firstLit, PenumbraScene::kEdge - s.halfWidth, 0.1);
    // A delta sun's shadow is hard: dark just under the edge, full light just beside it.
    PenumbraScene hard;
    hard.o.sunAngularRadius = 0.0;
    EXPECT_EQ(hard.pathMean(PenumbraScene::kEdge - 0.05, 16), 0.0);
    EXPECT_NEAR(hard.pathMean(PenumbraScene::kEdge + 0.05, 16), full, 1e-5);
}

TEST(PathTraceSun, SkyVisibilitySeesTheSameSoftSun) {
    // The sky visibility renderer's spiral of kSunDiskRays shadow rays over the disk: the same
    // profile within the spiral's 1/16 steps.
    const PenumbraScene s;
    for (int i = -6; i <= 6; ++i) {
        const double x = PenumbraScene::kEdge + i * 0.2 * s.halfWidth;
        auto camera = Camera::create({x, 1.5, 4.3}, 0.0, -90.0, 0.01, 1, 1);
        ASSERT_TRUE(camera.ok());
        SkyVisibilityOptions options;
        options.rays = 1;
        auto image = renderSkyVisibility(s.world, *camera, s.o, options);
        ASSERT_TRUE(image.ok());
        EXPECT_NEAR(image->radiance.at(0, 0, 0), s.expected(x), 0.08 * s.expected(40.0))
            << "x " << x;
    }
}

}  // namespace
