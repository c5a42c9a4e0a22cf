// The GPU voxel path tracer against its CPU reference (PathTracer) on whatever Vulkan device is
// present (lavapipe on CPU-only machines; skipped, saying why, without one): the random numbers
// bit for bit, the mean images within their standard errors, the CPU tracer's analytic answers
// (furnace, sky-lit plane, sun at 45 degrees), progressive passes, determinism, emitter sampling
// with MIS, and refusals. Images are tiny and sample counts low: lavapipe runs the shader on the
// CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "gpu/shaders/shared/path_rng.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/path_trace_gpu.h"
#include "voxel/path_trace_gpu_support.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr double kPi = 3.14159265358979323846;

bool sameImage(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), sizeof(float) * a.width() * a.height() * 3) == 0;
}

TEST(PathTraceGpu, SharedRandomNumbersAreTheCpusBitForBit) {
    // The GPU's 32-bit-word SplitMix64 against PathRng's 64-bit one, seeds with high bits set.
    namespace sh = gpu::shared;
    for (std::uint64_t seed :
         {std::uint64_t(1), std::uint64_t(0xdeadbeefcafef00d), ~std::uint64_t(0)}) {
        for (std::uint32_t pixel : {0u, 7u, 123457u, (1u << 26) - 1}) {
            for (std::uint32_t sample : {0u, 1u, 999u, (1u << 20) - 1}) {
                PathRng cpu(seed, pixel, sample);
                sh::uvec2 state = sh::pathRngKey(
                    sh::uvec2(std::uint32_t(seed), std::uint32_t(seed >> 32)), pixel, sample);
                for (int n = 0; n < 12; ++n) {
                    ASSERT_EQ(sh::pathRngNext(state), cpu.next())
                        << seed << " " << pixel << " " << sample << " #" << n;
                }
            }
        }
    }
    // The pieces: a 64-bit multiply with carries across the words.
    const std::uint64_t a = 0xfedcba9876543210ull, b = 0x0f1e2d3c4b5a6978ull;
    const sh::uvec2 p = sh::pathMul64(sh::uvec2(std::uint32_t(a), std::uint32_t(a >> 32)),
                                      sh::uvec2(std::uint32_t(b), std::uint32_t(b >> 32)));
    EXPECT_EQ((std::uint64_t(p.y) << 32) | p.x, a * b);
    EXPECT_EQ(sh::pathMulHigh(0xffffffffu, 0xffffffffu), 0xfffffffeu);
}

// A small scene with noise everywhere: a floor, a wall with a cutout-free texture slot, a sun,
// a gradient sky, the procedural face texture.
struct NoisyScene {
    VoxelWorld world = makeWorld({16, 8, 16});
    ShadeOptions o;
    Camera camera = *Camera::lookAt({1.0, 5.0, 1.0}, {9.0, 1.0, 9.0}, 60.0, 16, 12);
    NoisyScene() {
        for (int z = 0; z < 16; ++z)
            for (int x = 0; x < 16; ++x) {
                world.set(x, 0, z, Voxel{200, 180, 150, 255});
                if (x == 10)
                    for (int y = 1; y < 6; ++y) world.set(x, y, z, Voxel{90, 160, 90, 255});
            }
        world.set(6, 1, 6, Voxel{250, 80, 60, 255});
        world.refreshEmptySpace();
        o.skyTop = Rgb(0.3f, 0.5f, 1.0f);
        o.skyHorizon = Rgb(1.0f, 0.9f, 0.8f);
    }
};

TEST(PathTraceGpu, MeanImageAgreesWithTheCpuWithinItsStandardError) {
    REQUIRE_CONTEXT(context);
    const NoisyScene s;
    PathTraceOptions p;
    p.samplesPerPixel = 32;
    expectParity(*context, s.world, s.camera, s.o, p, nullptr, "noisy scene");
}

// The Preetham clear sky lights the paths (sky_model.h): each backend evaluates the same
// coefficients.
TEST(PathTraceGpu, PreethamSkyAgreesWithTheCpu) {
    REQUIRE_CONTEXT(context);
    NoisyScene s;
    s.o.skyModel = ShadeOptions::SkyModel::Preetham;
    s.o.skyTurbidity = 5.0f;
    s.o.skyZenithLuminance = 0.8f;
    s.o.sunDirection = Vec3(0.6f, 0.5f, -0.3f);
    PathTraceOptions p;
    p.samplesPerPixel = 32;
    expectParity(*context, s.world, s.camera, s.o, p, nullptr, "Preetham sky");
}

// Texture slots: an opaque texture on the wall, cutout leaves (every other texel a hole, which
// camera, bounce and shadow rays pass) over the floor, the procedural texture elsewhere.
TEST(PathTraceGpu, TexturesAndCutoutsAgreeWithTheCpu) {
    REQUIRE_CONTEXT(context);
    NoisyScene s;
    TextureSet textures;
    Texture opaque{"opaque", 4, 4, {}, 0.0f};
    for (int i = 0; i < 16; ++i) {
        opaque.texels.push_back({0.4f + 0.1f * (i % 4), 0.6f, 0.3f + 0.05f * (i / 4), 1.0f});
    }
    Texture holes{"holes", 4, 4, {}, std::nullopt};
    for (int i = 0; i < 16; ++i) {
        holes.texels.push_back({0.3f, 0.8f, 0.2f, ((i + i / 4) % 2) ? 0.0f : 1.0f});
    }
    ASSERT_TRUE(textures.add(opaque).ok());
    ASSERT_TRUE(textures.add(holes).ok());
    for (int z = 0; z < 16; ++z)
        for (int y = 1; y < 6; ++y) s.world.set(10, y, z, Voxel{255, 255, 255, alphaForSlot(0)});
    for (int z = 2; z < 9; ++z)
        for (int x = 2; x < 9; ++x) s.world.set(x, 4, z, Voxel{255, 255, 255, alphaForSlot(1)});
    s.world.refreshEmptySpace();
    s.o.textures = true;
    PathTraceOptions p;
    p.samplesPerPixel = 32;
    expectParity(*context, s.world, s.camera, s.o, p, &textures, "textures and cutouts");
}

TEST(PathTraceGpu, FurnaceShowsEmissionOverOneMinusAlbedo) {
    REQUIRE_CONTEXT(context);
    VoxelWorld world = makeWorld({8, 8, 8});
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                if (x == 0 || y == 0 || z == 0 || x == 7 || y == 7 || z == 7) {
                    world.set(x, y, z, kWhite);
                }
            }
    world.refreshEmptySpace();
    const float a = 0.6f, e = 0.5f;
    ShadeOptions o = plainLight(a, Rgb(e), Rgb(10.0f));  // the sky is never seen
    o.sunIrradiance = Rgb(5.0f);                         // nor the sun
    const Camera camera = *Camera::create({4.0, 4.0, 4.0}, 30.0, 10.0, 90.0, 8, 6);
    PathTraceOptions p;
    p.samplesPerPixel = 128;
    p.maxBounces = kMaxPathBounces;
    const PathTraceImage image = traceGpu(*context, world, camera, o, p);
    const double expected = e / (1.0 - a);
    double mean = 0.0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const double l = image.radiance.at(x, y, 1), se = image.standardError.at(x, y, 1);
            EXPECT_GT(se, 0.0);
            EXPECT_NEAR(l, expected, 5.0 * se) << x << "," << y;
            mean += l / 48.0;
        }
    EXPECT_NEAR(mean, expected, 0.02 * expected);
    // Two reflections at most, bounce rays alone: E (1 + a + a^2) with no noise at all.
    p.maxBounces = 2;
    p.sampleEmitters = false;
    p.samplesPerPixel = 8;
    const PathTraceImage two = traceGpu(*context, world, camera, o, p);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_NEAR(two.radiance.at(x, y, 0), e * (1.0 + a + a * a), 1e-5);
            EXPECT_EQ(two.standardError.at(x, y, 0), 0.0f);
        }
}

Camera lookingDown() {
    return *Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 8, 8);
}

TEST(PathTraceGpu, SkyLitPlaneAndTheSunAtFortyFiveDegrees) {
    REQUIRE_CONTEXT(context);
    const VoxelWorld world = floorWorld();
    const float a = 0.7f, sky = 1.5f;
    ShadeOptions o = plainLight(a, Rgb(0.0f), Rgb(sky));
    PathTraceOptions p;
    p.samplesPerPixel = 4;
    const PathTraceImage lit = traceGpu(*context, world, lookingDown(), o, p);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_NEAR(lit.radiance.at(x, y, 0), a * sky, 1e-5);
            EXPECT_EQ(lit.standardError.at(x, y, 0), 0.0f);  // no noise
        }
    p.maxBounces = 0;  // no reflection at all: the floor is black
    EXPECT_EQ(traceGpu(*context, world, lookingDown(), o, p).radiance.at(4, 4, 0), 0.0f);
    p.maxBounces = 8;
    const float sunE = 3.0f, b = 0.5f, dim = 0.25f;
    o = plainLight(b, Rgb(0.0f), Rgb(dim));
    o.sunIrradiance = Rgb(sunE);
    o.sunDirection = {0.0f, 1.0f, 1.0f};  // 45 degrees up
    const double expected = b * dim + b * sunE * std::cos(kPi / 4.0) / kPi;
    EXPECT_NEAR(traceGpu(*context, world, lookingDown(), o, p).radiance.at(2, 5, 2), expected,
                1e-5);
    o.sunDirection = {0.0f, -1.0f, 1.0f};  // below the horizon: no sun
    EXPECT_NEAR(traceGpu(*context, world, lookingDown(), o, p).radiance.at(2, 5, 2), b * dim, 1e-5);
}

TEST(PathTraceGpu, ProgressivePassesAndDeterminism) {
    REQUIRE_CONTEXT(context);
    const NoisyScene s;
    PathTraceOptions p;
    p.samplesPerPixel = 16;
    const PathTraceImage one = traceGpu(*context, s.world, s.camera, s.o, p);
    EXPECT_TRUE(sameImage(traceGpu(*context, s.world, s.camera, s.o, p).radiance, one.radiance));
    auto tracer = PathTracerGpu::create(*context, s.world, s.camera, s.o, p);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    ASSERT_TRUE(tracer->addSamples(8).ok());
    ASSERT_TRUE(tracer->addSamples(8).ok());
    EXPECT_EQ(tracer->samplesDone(), 16);
    EXPECT_GE(tracer->lastGpuMilliseconds(), 0.0);
    // The same samples; the float sums of a pass round differently, so equal to float precision.
    const PathTraceImage two = tracer->image();
    for (int y = 0; y < s.camera.height(); ++y)
        for (int x = 0; x < s.camera.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const float a = one.radiance.at(x, y, c), b = two.radiance.at(x, y, c);
                ASSERT_NEAR(a, b, 1e-5f * std::max(a, 1.0f)) << x << "," << y;
                ASSERT_NEAR(one.standardError.at(x, y, c), two.standardError.at(x, y, c),
                            1e-4f * std::max(a, 1.0f))
                    << x << "," << y;
            }
    EXPECT_NEAR(two.relativeError, one.relativeError, 1e-4 * one.relativeError);
    p.seed = 2;
    EXPECT_FALSE(sameImage(traceGpu(*context, s.world, s.camera, s.o, p).radiance, one.radiance));
    // Samples beyond a download's worth go in several submissions: the same image.
    p.seed = 1;
    p.samplesPerPixel = kPathSamplesPerDownload + 8;
    const PathTraceImage many = traceGpu(*context, s.world, s.camera, s.o, p);
    const PathTraceImage manyCpu = traceCpu(s.world, s.camera, s.o, p);
    double gpuSum = 0.0, cpuSum = 0.0;
    for (int y = 0; y < s.camera.height(); ++y)
        for (int x = 0; x < s.camera.width(); ++x) {
            gpuSum += many.radiance.at(x, y, 1);
            cpuSum += manyCpu.radiance.at(x, y, 1);
        }
    EXPECT_NEAR(gpuSum, cpuSum, 0.01 * cpuSum);
}

// A closed grey room lit by one small emissive block out of view (path_trace_test.cpp's): the
// GPU's emitter sampling with MIS agrees with the CPU's and with bounce rays alone, with less
// noise.
TEST(PathTraceGpu, EmitterSamplingWithMisOnALampRoom) {
    REQUIRE_CONTEXT(context);
    VoxelWorld world = makeWorld({12, 8, 12});
    for (int z = 0; z < 12; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 12; ++x) {
                if (x == 0 || y == 0 || z == 0 || x == 11 || y == 7 || z == 11) {
                    world.set(x, y, z, Voxel{180, 180, 180, 255});
                }
            }
    world.set(3, 1, 8, Voxel{255, 255, 255, 1});  // texture slot 0: the lamp's material
    world.refreshEmptySpace();
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    const Material lamp = lampMaterial(Rgb(20.0f, 15.0f, 10.0f));
    ASSERT_TRUE(o.materials.setSlot(0, lamp).ok());
    const Camera camera = *Camera::lookAt({6.0, 4.0, 7.0}, {6.0, 2.0, 0.5}, 70.0, 12, 9);
    PathTraceOptions p;
    p.samplesPerPixel = 64;
    const PathTraceImage mis = traceGpu(*context, world, camera, o, p);
    const PathTraceImage cpu = traceCpu(world, camera, o, p);
    p.sampleEmitters = false;
    const PathTraceImage bounce = traceGpu(*context, world, camera, o, p);
    double misMean = 0, cpuMean = 0, bounceMean = 0, misSe = 0, bounceSe = 0;
    const int pixels = 12 * 9;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) {
            misMean += mis.radiance.at(x, y, 1) / pixels;
            cpuMean += cpu.radiance.at(x, y, 1) / pixels;
            bounceMean += bounce.radiance.at(x, y, 1) / pixels;
            misSe += mis.standardError.at(x, y, 1) / pixels;
            bounceSe += bounce.standardError.at(x, y, 1) / pixels;
        }
    std::printf(
        "lamp room: gpu mis %.5f (rel. error %.3f), cpu mis %.5f, gpu bounce %.5f "
        "(rel. error %.3f)\n",
        misMean, mis.relativeError, cpuMean, bounceMean, bounce.relativeError);
    EXPECT_GT(misMean, 0.0);
    // The same random numbers as the CPU: the means agree far better than their noise.
    EXPECT_NEAR(misMean, cpuMean, 0.01 * cpuMean);
    const double combined = std::hypot(misSe, bounceSe) / std::sqrt(double(pixels));
    EXPECT_NEAR(misMean, bounceMean, 5.0 * combined);
    EXPECT_LT(mis.relativeError, 0.5 * bounce.relativeError);
}

TEST(PathTraceGpu, RefusesBadInputWithTheFieldNamed) {
    REQUIRE_CONTEXT(context);
    const NoisyScene s;
    auto message = [&](const ShadeOptions& o, const PathTraceOptions& p) {
        auto r = PathTracerGpu::create(*context, s.world, s.camera, o, p);
        EXPECT_FALSE(r.ok());
        return r.ok() ? std::string() : r.error().message();
    };
    PathTraceOptions p;
    p.samplesPerPixel = 0;
    EXPECT_NE(message(s.o, p).find("samples per pixel must be in 1.."), std::string::npos);
    p = {};
    p.maxBounces = kMaxPathBounces + 1;
    EXPECT_NE(message(s.o, p).find("max bounces"), std::string::npos);
    p = {};
    ShadeOptions o = s.o;
    o.sunDirection = {std::nanf(""), 1.0f, 0.0f};
    EXPECT_NE(message(o, p).find("sun direction must be finite and non-zero"), std::string::npos);
    o = s.o;
    o.skyHorizon = Rgb(-1.0f);
    EXPECT_NE(message(o, p).find("sky horizon must be finite and >= 0"), std::string::npos);
    auto tracer = PathTracerGpu::create(*context, s.world, s.camera, s.o, {});
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    EXPECT_FALSE(tracer->addSamples(0).ok());
    EXPECT_FALSE(tracer->addSamples(kMaxPathSamples + 1).ok());
    EXPECT_EQ(tracer->samplesDone(), 0);
    EXPECT_TRUE(std::isnan(tracer->image().relativeError));
}

}  // namespace
