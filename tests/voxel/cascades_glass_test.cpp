// The voxel radiance cascades' chains through glass (docs/algorithms/voxel-radiance-cascades.md
// §4.2): a floor under a glass ceiling and a sky, and a lamp behind a glass wall, each against
// the same world with the glass taken away; the ratio is the straight line's transmittance,
// (1 - F)^2 exp(-sigma d / cos), averaged over the directions that carry the light; a floor
// under a glass slab lying on it (one interface), its sun and its picture seen through the slab.
// And glass sends back only what it does not let through.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/voxel/radiance_cascades.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/solver_sun.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr double kPi = 3.14159265358979323846;

constexpr Voxel kGlass{255, 255, 255, 1};  // texture slot 0
constexpr Voxel kLamp{255, 255, 255, 2};   // texture slot 1

Rgb solvedIrradiance(const VoxelWorld& world, const ShadeOptions& o, Int3 voxel, Int3 normal,
                     Vec3d point) {
    auto cascades = RadianceCascades::create(world, nullptr, o);
    EXPECT_TRUE(cascades.ok()) << cascades.error().message();
    cascades->solve();
    return cascades->indirectIrradiance(voxel, normal, point);
}

// What passes a smooth slab `thickness` voxels thick of index 1.5 and absorption sigma along a
// straight line at cosine mu to its normal.
double slabTransmittance(double mu, double sigma, double thickness, const ShadeOptions& o) {
    const double f = dielectricFresnel(float(mu), 1.5f, o.fresnel);
    return (1.0 - f) * (1.0 - f) * std::exp(-sigma * thickness / mu);
}

// A black floor (y = 0) under a glass ceiling two voxels thick (y = 2..3) across the whole
// world, or under nothing, and a uniform sky.
VoxelWorld floorUnderACeiling(bool glass) {
    VoxelWorld world = makeWorld({32, 6, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) {
            world.set(x, 0, z, kWhite);
            if (glass) world.set(x, 2, z, kGlass), world.set(x, 3, z, kGlass);
        }
    world.refreshEmptySpace();
    return world;
}

TEST(CascadesGlass, SkyThroughAGlassCeilingIsFresnelAndBeerLambert) {
    const float sigma = 0.1f;
    ShadeOptions o = plainLight(0.0f, Rgb(0.0f), Rgb(1.0f));
    ASSERT_TRUE(o.materials.setSlot(0, glass(Rgb(sigma))).ok());
    const Int3 voxel{16, 0, 16}, up{0, 1, 0};
    const Vec3d point{16.5, 1.0, 16.5};
    const Rgb open = solvedIrradiance(floorUnderACeiling(false), o, voxel, up, point);
    const Rgb covered = solvedIrradiance(floorUnderACeiling(true), o, voxel, up, point);
    // The cosine-weighted mean of the slab's transmittance over the sky.
    constexpr int kSteps = 4096;
    double expected = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;
        expected += 2.0 * mu * slabTransmittance(mu, sigma, 2.0, o) / kSteps;
    }
    ASSERT_GT(open.g, 3.0f);  // pi under the open sky, less what leaves by the world's sides
    EXPECT_NEAR(covered.g / open.g, expected, 0.03 * expected);
    // Before glass let the chains through, the ceiling stopped them: the floor saw only the
    // ceiling's diffuse light.
    EXPECT_GT(covered.g / open.g, 0.5 * expected);
}

// The floor's face under a slab of glass lying on it is a probe: its light comes in through one
// interface, (1 - F) exp(-sigma d / cos); its sun rays start inside the glass and leave through
// it; and the camera looking down through the slab sees the floor, lit.
TEST(CascadesGlass, FloorUnderAGlassSlabIsLitThroughIt) {
    const float sigma = 0.1f, albedo = 0.6f;
    ShadeOptions o = plainLight(albedo, Rgb(0.0f), Rgb(1.0f));
    ASSERT_TRUE(o.materials.setSlot(0, glass(Rgb(sigma))).ok());
    VoxelWorld world = makeWorld({32, 6, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) {
            world.set(x, 0, z, kWhite);
            world.set(x, 1, z, kGlass), world.set(x, 2, z, kGlass);
        }
    world.refreshEmptySpace();
    auto cascades = RadianceCascades::create(world, nullptr, o);
    ASSERT_TRUE(cascades.ok()) << cascades.error().message();
    cascades->solve();
    const Rgb under = cascades->indirectIrradiance({16, 0, 16}, {0, 1, 0}, {16.5, 1.0, 16.5});
    // The sky through one interface, plus what the slab's underside sends back down (its share
    // 1 - mean(1 - F) of the floor's light: a few percent more).
    constexpr int kSteps = 4096;
    double sky = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;
        const double f = dielectricFresnel(float(mu), 1.5f, o.fresnel);
        sky += 2.0 * mu * (1.0 - f) * std::exp(-sigma * 2.0 / mu) * kPi / kSteps;
    }
    EXPECT_GT(under.g, 0.97 * sky);
    EXPECT_LT(under.g, 1.08 * sky);
    // A sun ray from the floor leaves through the slab's top.
    const Vec3d l = normalize(Vec3d{0.0, 1.0, 1.0});
    const double cosL = l.y;
    const double sun =
        (1.0 - dielectricFresnel(float(cosL), 1.5f, o.fresnel)) * std::exp(-sigma * 2.0 / cosL);
    EXPECT_NEAR(sunRayTransmittance(world, nullptr, {{16.5, 1.0, 16.5}, l}, o).g, sun, 1e-5);
    // Straight down through the slab: its mirror reflection of the sky, and the floor through
    // it, (1 - F) exp(-2 sigma) albedo E / pi.
    auto cam = Camera::create({16.5, 5.0, 16.5}, 0.0, -90.0, 10.0, 4, 4);
    ASSERT_TRUE(cam.ok());
    auto image = cascades->render(*cam);
    ASSERT_TRUE(image.ok());
    const double f0 = dielectricFresnel(1.0f, 1.5f, o.fresnel);
    const double seen = f0 + (1.0 - f0) * std::exp(-2.0 * sigma) * albedo * under.g / kPi;
    EXPECT_NEAR(image->at(2, 2, 1), seen, 0.03 * seen);
}

// A lamp (albedo 0) facing a receiver 9 voxels away, with a glass wall two voxels thick between
// them across the whole world, or no wall; the rest black, no sky.
VoxelWorld lampBehindAWall(bool glass) {
    VoxelWorld world = makeWorld({16, 16, 16});
    world.set(8, 8, 2, kLamp);
    world.set(8, 8, 12, kWhite);
    if (glass) {
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) world.set(x, y, 5, kGlass), world.set(x, y, 6, kGlass);
    }
    world.refreshEmptySpace();
    return world;
}

TEST(CascadesGlass, LampBehindAGlassWallLightsTheOtherSide) {
    const float sigma = 0.2f;
    ShadeOptions o = plainLight(0.0f, Rgb(0.0f), Rgb(0.0f));
    Material lamp = lampMaterial(Rgb(10.0f));
    lamp.albedo = Rgb(0.0f);
    ASSERT_TRUE(o.materials.setSlot(0, glass(Rgb(sigma))).ok());
    ASSERT_TRUE(o.materials.setSlot(1, lamp).ok());
    const Int3 voxel{8, 8, 12}, back{0, 0, -1};
    const Vec3d point{8.5, 8.5, 12.0};
    const Rgb open = solvedIrradiance(lampBehindAWall(false), o, voxel, back, point);
    const Rgb walled = solvedIrradiance(lampBehindAWall(true), o, voxel, back, point);
    ASSERT_GT(open.r, 0.0f);
    // Almost head-on: the lamp's face is 1 voxel wide 9 voxels away.
    const double expected = slabTransmittance(1.0, sigma, 2.0, o);
    EXPECT_NEAR(walled.r / open.r, expected, 0.01 * expected);
}

// A sunlit glass column on a black floor, seen by a black receiver 4 voxels in front of the face
// it turns to the sun: that face sends back only the share its transmission lobe does not take,
// 1 - (cosine-weighted mean of 1 - F), about 0.09 for index 1.5, of what an opaque face of the
// same colour sends (the receiver sees nothing else lit, through the glass or beside it).
TEST(CascadesGlass, LitGlassSendsBackOnlyWhatItDoesNotLetThrough) {
    auto received = [](bool clear) {
        VoxelWorld world = makeWorld({16, 12, 16});
        for (int z = 0; z < 16; ++z)
            for (int x = 0; x < 16; ++x) world.set(x, 0, z, kWhite);
        for (int y = 1; y < 5; ++y) world.set(8, y, 8, kGlass);
        world.set(8, 2, 13, kWhite);
        world.refreshEmptySpace();
        ShadeOptions o = plainLight(0.0f, Rgb(0.0f), Rgb(0.0f));
        Material block = glass();
        if (!clear) block.transmission = 0.0f;
        EXPECT_TRUE(o.materials.setSlot(0, block).ok());
        o.sunIrradiance = Rgb(10.0f);
        o.sunDirection = {0.0f, 1.0f, 1.0f};
        return solvedIrradiance(world, o, {8, 2, 13}, {0, 0, -1}, {8.5, 2.5, 13.0});
    };
    const Rgb opaque = received(false), clear = received(true);
    ASSERT_GT(opaque.r, 0.0f);
    constexpr int kSteps = 4096;
    double passed = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;
        passed += 2.0 * mu * (1.0 - dielectricFresnel(float(mu), 1.5f, ShadeOptions{}.fresnel));
    }
    const double share = 1.0 - passed / kSteps;
    EXPECT_NEAR(clear.r / opaque.r, share, 0.02 * share);
}

}  // namespace
