// The GPU voxel path tracer's materials and sun disk against the CPU tracer (the same random
// numbers, so mean images agree far within their standard errors) and against the CPU tests'
// analytic answers: a mirror floor shows albedo x sky without noise, a glass slab passes the
// Fresnel series times Beer-Lambert. Images are tiny: lavapipe runs the shader on the CPU.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/shaders/shared/optics.h"
#include "voxel/path_trace_gpu_support.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

// A default-material floor (a rough dielectric, ior 1.5), a block of slot 0's material and a
// default-material pillar under a gradient sky and the sun.
struct MaterialScene {
    VoxelWorld world = makeWorld({16, 8, 16});
    ShadeOptions o;
    Camera camera = *Camera::lookAt({2.0, 5.0, 1.0}, {8.0, 1.5, 8.0}, 60.0, 16, 12);
    explicit MaterialScene(const Material& block) {
        for (int z = 0; z < 16; ++z)
            for (int x = 0; x < 16; ++x) world.set(x, 0, z, Voxel{200, 180, 150, 255});
        for (int y = 1; y < 4; ++y)
            for (int z = 6; z < 9; ++z)
                for (int x = 5; x < 9; ++x) world.set(x, y, z, Voxel{230, 230, 240, 1});
        for (int y = 1; y < 5; ++y) world.set(11, y, 9, Voxel{90, 160, 90, 255});
        world.refreshEmptySpace();
        o.textures = false;
        o.skyTop = Rgb(0.3f, 0.5f, 1.0f);
        o.skyHorizon = Rgb(1.0f, 0.9f, 0.8f);
        o.sunDirection = {0.4f, 1.0f, 0.3f};
        EXPECT_TRUE(o.materials.setSlot(0, block).ok());
    }
};

TEST(PathTraceGpuMaterials, GlassWithAbsorptionAgreesWithTheCpu) {
    REQUIRE_CONTEXT(context);
    const MaterialScene s(glass(Rgb(0.1f, 0.3f, 0.6f)));
    PathTraceOptions p;
    p.samplesPerPixel = 32;
    expectParity(*context, s.world, s.camera, s.o, p, nullptr, "glass with absorption");
    // The options the GPU reads from its own push constants, whatever the ray caster's lighting:
    // Schlick's Fresnel, and refraction off (the glass opaque).
    MaterialScene schlick(glass(Rgb(0.1f, 0.3f, 0.6f)));
    schlick.o.fresnel = ShadeOptions::FresnelModel::Schlick;
    expectParity(*context, schlick.world, schlick.camera, schlick.o, p, nullptr, "glass, Schlick");
    MaterialScene opaque(glass(Rgb(0.1f, 0.3f, 0.6f)));
    opaque.o.refraction = false;
    expectParity(*context, opaque.world, opaque.camera, opaque.o, p, nullptr, "glass, opaque");
}

TEST(PathTraceGpuMaterials, MirrorAndRoughMetalAgreeWithTheCpu) {
    REQUIRE_CONTEXT(context);
    PathTraceOptions p;
    p.samplesPerPixel = 32;
    const MaterialScene mirror(metal(0.0f, Rgb(0.95f, 0.8f, 0.6f)));
    expectParity(*context, mirror.world, mirror.camera, mirror.o, p, nullptr, "metal mirror");
    const MaterialScene rough(metal(0.4f, Rgb(0.9f, 0.7f, 0.5f)));
    expectParity(*context, rough.world, rough.camera, rough.o, p, nullptr, "rough metal");
    // A narrow lobe (roughness 0.05, alpha 0.0025) meets the sun's disk through both strategies.
    MaterialScene narrow(metal(0.05f, Rgb(0.9f)));
    narrow.o.sunAngularRadius = 2.0 * 3.14159265358979 / 180.0;
    expectParity(*context, narrow.world, narrow.camera, narrow.o, p, nullptr, "narrow metal");
}

// The default material everywhere (the block too) and a 2-degree sun: light samples and bounce
// rays both find the disk, combined by the power heuristic.
TEST(PathTraceGpuMaterials, DefaultMaterialUnderATwoDegreeSunAgreesWithTheCpu) {
    REQUIRE_CONTEXT(context);
    MaterialScene s{defaultMaterial()};
    s.o.sunAngularRadius = 2.0 * 3.14159265358979 / 180.0;
    PathTraceOptions p;
    p.samplesPerPixel = 32;
    expectParity(*context, s.world, s.camera, s.o, p, nullptr, "default material, 2-degree sun");
}

TEST(PathTraceGpuMaterials, MirrorFloorShowsAlbedoTimesSky) {
    REQUIRE_CONTEXT(context);
    const VoxelWorld world = floorWorld();
    const float sky = 1.5f;
    ShadeOptions o = plainLight(1.0f, Rgb(0.0f), Rgb(sky));
    const Rgb albedo(0.9f, 0.6f, 0.3f);
    ASSERT_TRUE(o.materials.setPlain(metal(0.0f, albedo)).ok());
    const Camera camera = *Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 8, 8);
    PathTraceOptions p;
    p.samplesPerPixel = 4;
    const PathTraceImage image = traceGpu(*context, world, camera, o, p);
    // Schlick's (1 - cos)^5 < 1e-9 within 10 degrees of the normal; a delta mirror has no noise.
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(image.radiance.at(x, y, c), albedo[c] * sky, 1e-5) << x << "," << y;
                EXPECT_EQ(image.standardError.at(x, y, c), 0.0f);
            }
}

// A floor under a glass pane lit by the real sun through it (PathTraceOptions::sunThroughGlass:
// sun light sampling follows the shadow rays through the pane) and a gradient sky, seen from
// between floor and pane.
TEST(PathTraceGpuMaterials, SunThroughAPaneAgreesWithTheCpu) {
    REQUIRE_CONTEXT(context);
    const VoxelWorld world = paneOverAFloor();
    ShadeOptions o = plainLight(0.8f, Rgb(0.0f), Rgb(0.0f));
    o.skyTop = Rgb(0.3f, 0.5f, 1.0f);
    o.skyHorizon = Rgb(1.0f, 0.9f, 0.8f);
    o.sunIrradiance = Rgb(3.0f);
    o.sunDirection = {0.3f, 1.0f, 0.2f};
    o.sunAngularRadius = 0.0047;
    ASSERT_TRUE(o.materials.setSlot(0, glass(Rgb(0.05f, 0.1f, 0.2f))).ok());
    const Camera camera = *Camera::lookAt({4.0, 3.5, 4.0}, {12.0, 0.0, 12.0}, 60.0, 16, 12);
    PathTraceOptions p;
    p.samplesPerPixel = 16;
    expectParity(*context, world, camera, o, p, nullptr, "sun through a pane");
    // The floor is lit through the pane: far brighter than the sky alone makes it.
    const PathTraceImage lit = traceGpu(*context, world, camera, o, p);
    o.sunIrradiance = Rgb(0.0f);
    const PathTraceImage sky = traceGpu(*context, world, camera, o, p);
    EXPECT_GT(lit.radiance.at(8, 8, 0), 2.0f * sky.radiance.at(8, 8, 0));
}

// A glowing wall (z = 0) seen through a clear glass slab three voxels thick (z in [6, 9)) that
// fills the world's cross-section; the sky is black. What crosses is E (1 - F)^2 t / (1 - F^2 t^2),
// t = exp(-3 sigma_a): the series of internal reflections.
TEST(PathTraceGpuMaterials, GlassSlabPassesTheFresnelSeriesAndBeerLambert) {
    REQUIRE_CONTEXT(context);
    const double f = gpu::shared::fresnelDielectricExact(1.0f, 1.0f, 1.5f);  // 0.04
    const float emission = 2.0f;
    for (const float sigma : {0.0f, 0.2f}) {
        const VoxelWorld world = slabBeforeAWall();
        ShadeOptions o = plainLight(0.0f, Rgb(0.0f), Rgb(0.0f));
        ASSERT_TRUE(o.materials.setSlot(0, glass(Rgb(sigma))).ok());
        Material wall;
        wall.name = "wall";
        wall.albedo = Rgb(0.0f);
        wall.emission = Rgb(emission);
        ASSERT_TRUE(o.materials.setSlot(1, wall).ok());
        // Nearly along -z (a 1-degree field of view).
        const Camera camera = *Camera::lookAt({4.3, 4.6, 14.0}, {4.3, 4.6, 0.0}, 1.0, 4, 4);
        PathTraceOptions p;
        p.samplesPerPixel = 1024;
        p.maxBounces = kMaxPathBounces;
        p.rouletteAfter = kMaxPathBounces;
        const PathTraceImage image = traceGpu(*context, world, camera, o, p);
        const double t = std::exp(-sigma * 3.0);
        const double expected = emission * (1 - f) * (1 - f) * t / (1 - f * f * t * t);
        double mean = 0.0, variance = 0.0;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const double l = image.radiance.at(x, y, 0), se = image.standardError.at(x, y, 0);
                EXPECT_GT(se, 0.0);
                EXPECT_NEAR(l, expected, 4.0 * se) << x << "," << y << " sigma " << sigma;
                mean += l / 16.0;
                variance += se * se / 256.0;
            }
        const double se = std::sqrt(variance);
        EXPECT_NEAR(mean, expected, 4.0 * se) << "sigma " << sigma;
        // Not the opaque or the single-interface answer.
        EXPECT_GT(std::abs(mean - emission * (1 - f) * t), 8.0 * se) << "sigma " << sigma;
    }
}

}  // namespace
