// The voxel path tracer against analytic answers: the furnace (a closed box of albedo a and
// emission E shows E / (1 - a)), a plane under a uniform, gradient or CIE overcast sky and a
// sun, a white furnace (albedo 1 under a uniform sky shows the sky), determinism and the
// standard error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "luxel/core/parallel.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/sky_model.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr double kPi = 3.14159265358979323846;

void finish(VoxelWorld& world) {
    world.refreshEmptySpace();
}

Camera lookingDown() {
    auto camera = Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 8, 8);
    EXPECT_TRUE(camera.ok());
    return *camera;
}

PathTraceImage trace(const VoxelWorld& world, const Camera& camera, const ShadeOptions& o,
                     PathTraceOptions p) {
    auto image = pathTrace(world, camera, o, p);
    EXPECT_TRUE(image.ok()) << image.error().message();
    return std::move(*image);
}

// Channel 0 over the image's pixels: the mean of their values and of their standard errors.
struct PixelMeans {
    double value = 0.0, standardError = 0.0;
};
PixelMeans pixelMeans(const PathTraceImage& image) {
    const int w = image.radiance.width(), h = image.radiance.height();
    PixelMeans m;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            m.value += image.radiance.at(x, y, 0) / (w * h);
            m.standardError += image.standardError.at(x, y, 0) / (w * h);
        }
    return m;
}

TEST(PathTrace, FurnaceBoxShowsEmissionOverOneMinusAlbedo) {
    // A closed 8^3 box with walls one voxel thick, the camera in the middle.
    VoxelWorld world = makeWorld({8, 8, 8});
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                const bool wall = x == 0 || y == 0 || z == 0 || x == 7 || y == 7 || z == 7;
                if (wall) world.set(x, y, z, kWhite);
            }
    finish(world);
    const float a = 0.6f, e = 0.5f;
    ShadeOptions o = plainLight(a, Rgb(e), Rgb(10.0f));  // the sky is never seen
    o.sunIrradiance = Rgb(5.0f);                         // nor the sun
    auto camera = Camera::create({4.0, 4.0, 4.0}, 30.0, 10.0, 90.0, 8, 6);
    ASSERT_TRUE(camera.ok());
    PathTraceOptions p;
    p.samplesPerPixel = 256;
    p.maxBounces = kMaxPathBounces;
    const PathTraceImage image = trace(world, *camera, o, p);
    const double expected = e / (1.0 - a);  // 1.25
    double mean = 0.0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const double l = image.radiance.at(x, y, 1), se = image.standardError.at(x, y, 1);
            EXPECT_GT(se, 0.0);
            EXPECT_NEAR(l, expected, 5.0 * se) << x << "," << y;
            mean += l / 48.0;
        }
    EXPECT_NEAR(mean, expected, 0.02 * expected);
    // Two reflections at most: E (1 + a + a^2). Without emitter sampling (every path walks
    // the same weights) noise-free; with it, the same mean.
    p.maxBounces = 2;
    p.sampleEmitters = false;
    const PathTraceImage two = trace(world, *camera, o, p);
    EXPECT_NEAR(two.radiance.at(3, 3, 0), e * (1.0 + a + a * a), 1e-5);
    EXPECT_NEAR(two.standardError.at(3, 3, 0), 0.0, 1e-5);
    p.sampleEmitters = true;
    const PixelMeans mis = pixelMeans(trace(world, *camera, o, p));
    EXPECT_GT(mis.standardError, 0.0);
    EXPECT_NEAR(mis.value, e * (1.0 + a + a * a), 5.0 * mis.standardError / std::sqrt(48.0));
}

// A closed grey room lit by one small emissive block: emitter sampling with MIS and bounce rays
// alone agree on the mean, and MIS has far less noise where the lamp lights the room unseen.
TEST(PathTrace, EmitterSamplingAgreesWithBounceRaysAndHasLessNoise) {
    VoxelWorld world = makeWorld({12, 8, 12});
    for (int z = 0; z < 12; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 12; ++x) {
                const bool wall = x == 0 || y == 0 || z == 0 || x == 11 || y == 7 || z == 11;
                if (wall) world.set(x, y, z, Voxel{180, 180, 180, 255});
            }
    world.set(3, 1, 8, Voxel{255, 255, 255, 1});  // texture slot 0: the lamp's material
    finish(world);
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    const Material lamp = lampMaterial(Rgb(20.0f, 15.0f, 10.0f));
    ASSERT_TRUE(o.materials.setSlot(0, lamp).ok());
    const PathEmitters emitters = PathEmitters::find(world, o.materials);
    ASSERT_EQ(emitters.size(), 1);
    // The density sample() reports is the one pdf() gives for the point sampled.
    const Vec3d from{8.5, 1.0, 3.5};
    const PathEmitters::Sample one = emitters.sample(from, 0.2f, 0.7f, 0.3f, 0.6f);
    ASSERT_GT(one.pdf, 0.0);
    EXPECT_NEAR(emitters.pdf(from, one.voxel, one.normal, from + one.direction * one.distance),
                one.pdf, 1e-9 * one.pdf);

    auto camera = Camera::lookAt({6.0, 4.0, 7.0}, {6.0, 2.0, 0.5}, 70.0, 12, 9);  // lamp behind
    ASSERT_TRUE(camera.ok());
    PathTraceOptions p;
    p.samplesPerPixel = 128;
    const PathTraceImage mis = trace(world, *camera, o, p);
    p.sampleEmitters = false;
    const PathTraceImage bounce = trace(world, *camera, o, p);
    double misMean = 0, bounceMean = 0, misSe = 0, bounceSe = 0;
    const int pixels = 12 * 9;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) {
            misMean += mis.radiance.at(x, y, 1) / pixels;
            bounceMean += bounce.radiance.at(x, y, 1) / pixels;
            misSe += mis.standardError.at(x, y, 1) / pixels;
            bounceSe += bounce.standardError.at(x, y, 1) / pixels;
        }
    EXPECT_GT(misMean, 0.0);
    // Pixel errors average down by sqrt(pixels) over the image (pixels are independent).
    const double combined = std::hypot(misSe, bounceSe) / std::sqrt(double(pixels));
    EXPECT_NEAR(misMean, bounceMean, 5.0 * combined);
    EXPECT_LT(mis.relativeError, 0.5 * bounce.relativeError);
}

TEST(PathTrace, PlaneUnderAUniformSkyShowsAlbedoTimesSky) {
    const VoxelWorld world = floorWorld();
    const float a = 0.7f, sky = 1.5f;
    const ShadeOptions o = plainLight(a, Rgb(0.0f), Rgb(sky));
    PathTraceOptions p;
    p.samplesPerPixel = 8;
    const PathTraceImage image = trace(world, lookingDown(), o, p);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_NEAR(image.radiance.at(x, y, 0), a * sky, 1e-5);
    // Only a sky reflected once: E = pi S, L = a E / pi = a S.
    p.maxBounces = 0;  // no reflection at all: the floor is black
    EXPECT_EQ(trace(world, lookingDown(), o, p).radiance.at(4, 4, 0), 0.0f);
}

TEST(PathTrace, PlaneAddsTheSunsLambertTerm) {
    const VoxelWorld world = floorWorld();
    const float a = 0.5f, sky = 0.25f, sunE = 3.0f;
    ShadeOptions o = plainLight(a, Rgb(0.0f), Rgb(sky));
    o.sunIrradiance = Rgb(sunE);
    o.sunDirection = {0.0f, 1.0f, 1.0f};  // 45 degrees up
    PathTraceOptions p;
    p.samplesPerPixel = 4;
    const PathTraceImage image = trace(world, lookingDown(), o, p);
    const double expected = a * sky + a * sunE * std::cos(kPi / 4.0) / kPi;
    EXPECT_NEAR(image.radiance.at(2, 5, 2), expected, 1e-5);
    // The sun below the horizon lights nothing.
    o.sunDirection = {0.0f, -1.0f, 1.0f};
    EXPECT_NEAR(trace(world, lookingDown(), o, p).radiance.at(2, 5, 2), a * sky, 1e-5);
}

TEST(PathTrace, PlaneUnderAGradientSkyMatchesTheCosineWeightedMean) {
    // sky = H + (T - H) sin(elevation); the cosine-weighted mean of sin(elevation) is 2/3.
    const VoxelWorld world = floorWorld();
    ShadeOptions o = plainLight(0.8f, Rgb(0.0f), Rgb(0.0f));
    o.skyHorizon = Rgb(1.0f);
    o.skyTop = Rgb(0.1f);
    PathTraceOptions p;
    p.samplesPerPixel = 2048;
    const PathTraceImage image = trace(world, lookingDown(), o, p);
    const double expected = 0.8 * (1.0 + (0.1 - 1.0) * 2.0 / 3.0);
    double mean = 0.0, se = 0.0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            mean += image.radiance.at(x, y, 0) / 64.0;
            se += image.standardError.at(x, y, 0) / 64.0;
        }
    EXPECT_GT(se, 0.0);
    EXPECT_NEAR(mean, expected, 4.0 * se / 8.0);  // 64 independent pixels: se / sqrt(64)
}

TEST(PathTrace, PlaneUnderTheCieOvercastSkyHasItsHorizontalIrradiance) {
    // L(theta) = Lz (1 + 2 cos theta) / 3 gives E = 7 pi Lz / 9 on the floor, L = a 7 Lz / 9.
    const VoxelWorld world = floorWorld();
    const float a = 0.6f, zenith = 1.8f;
    ShadeOptions o = plainLight(a, Rgb(0.0f), Rgb(0.0f));
    const SkyGradient sky = cieOvercastSky(Rgb(zenith));
    o.skyTop = sky.top;
    o.skyHorizon = sky.horizon;
    PathTraceOptions p;
    p.samplesPerPixel = 2048;
    const PixelMeans m = pixelMeans(trace(world, lookingDown(), o, p));
    EXPECT_GT(m.standardError, 0.0);
    EXPECT_NEAR(m.value, a * 7.0 * zenith / 9.0, 4.0 * m.standardError / 8.0);  // 64 pixels
}

// Pillars and a floor of albedo 1 under a uniform sky: every path ends in the sky with weight 1,
// so every pixel shows the sky (less what the bounce limit cuts), never more.
TEST(PathTrace, WhiteFurnaceConservesEnergy) {
    VoxelWorld world = makeWorld({24, 12, 24});
    for (int z = 0; z < 24; ++z)
        for (int x = 0; x < 24; ++x) {
            world.set(x, 0, z, kWhite);
            if (x % 6 == 2 && z % 5 == 1)
                for (int y = 1; y < 10; ++y) world.set(x, y, z, kWhite);
        }
    finish(world);
    const float sky = 2.0f;
    const ShadeOptions o = plainLight(1.0f, Rgb(0.0f), Rgb(sky));
    auto camera = Camera::lookAt({1.0, 8.0, 1.0}, {14.0, 1.0, 14.0}, 60.0, 12, 8);
    ASSERT_TRUE(camera.ok());
    PathTraceOptions p;
    p.samplesPerPixel = 32;
    p.maxBounces = kMaxPathBounces;
    const PathTraceImage image = trace(world, *camera, o, p);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 12; ++x) EXPECT_NEAR(image.radiance.at(x, y, 0), sky, 1e-4);
    // Albedo 0: each path shows only what it meets first (the emission or the sky), so a pixel
    // is a mix of the two where its samples see both and noise-free where they see one.
    const ShadeOptions black = plainLight(0.0f, Rgb(0.3f), Rgb(sky));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 12; ++x) {
            PathRng rng(5, std::uint64_t(y) * 12 + x, 0);
            const float l = tracePath(world, nullptr, camera->primaryRay(x, y), black, p, rng).r;
            EXPECT_TRUE(l == 0.3f || l == sky) << l;
        }
    const PathTraceImage direct = trace(world, *camera, black, p);
    int pure = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 12; ++x) {
            const float l = direct.radiance.at(x, y, 0);
            EXPECT_GE(l, 0.3f - 1e-6f);
            EXPECT_LE(l, sky + 1e-6f);
            if (direct.standardError.at(x, y, 0) == 0.0f) {
                EXPECT_TRUE(l == 0.3f || l == sky) << l;
                ++pure;
            }
        }
    EXPECT_GT(pure, 48);
}

// A small closed-off scene with noise everywhere: a floor, a wall, a sun, a gradient sky.
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
        finish(world);
        o.textures = false;
    }
};

bool sameImage(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), sizeof(float) * a.width() * a.height() * 3) == 0;
}

TEST(PathTrace, SameSeedSameImageForAnyThreadCountAndPassSplit) {
    const NoisyScene s;
    PathTraceOptions p;
    p.samplesPerPixel = 8;
    PathTraceImage one, two;
    {
        ThreadLimit limit(1);
        one = trace(s.world, s.camera, s.o, p);
    }
    {
        ThreadLimit limit(2);
        two = trace(s.world, s.camera, s.o, p);
    }
    EXPECT_TRUE(sameImage(one.radiance, two.radiance));
    EXPECT_TRUE(sameImage(one.standardError, two.standardError));
    // Two passes of 3 and 5 samples: the same sums in the same order.
    auto tracer = PathTracer::create(s.world, s.camera, s.o, p);
    ASSERT_TRUE(tracer.ok());
    ASSERT_TRUE(tracer->addSamples(3).ok());
    ASSERT_TRUE(tracer->addSamples(5).ok());
    EXPECT_EQ(tracer->samplesDone(), 8);
    EXPECT_TRUE(sameImage(tracer->image().radiance, one.radiance));
    p.seed = 2;
    EXPECT_FALSE(sameImage(trace(s.world, s.camera, s.o, p).radiance, one.radiance));
}

TEST(PathTrace, StandardErrorShrinksAsOneOverSquareRootOfSamples) {
    const NoisyScene s;
    PathTraceOptions p;
    p.samplesPerPixel = 16;
    const PathTraceImage few = trace(s.world, s.camera, s.o, p);
    p.samplesPerPixel = 64;
    const PathTraceImage many = trace(s.world, s.camera, s.o, p);
    ASSERT_GT(many.relativeError, 0.0);
    const double ratio = few.relativeError / many.relativeError;
    EXPECT_GT(ratio, 1.7);
    EXPECT_LT(ratio, 2.3);
    p.samplesPerPixel = 1;
    EXPECT_TRUE(std::isnan(trace(s.world, s.camera, s.o, p).relativeError));
}

TEST(PathTrace, RefusesBadInputWithTheFieldNamed) {
    const NoisyScene s;
    auto message = [&](const ShadeOptions& o, const PathTraceOptions& p) {
        auto r = pathTrace(s.world, s.camera, o, p);
        EXPECT_FALSE(r.ok());
        return r.ok() ? std::string() : r.error().message();
    };
    PathTraceOptions p;
    p.samplesPerPixel = 0;
    EXPECT_NE(message(s.o, p).find("samples per pixel must be in 1.."), std::string::npos);
    p.samplesPerPixel = kMaxPathSamples + 1;
    EXPECT_NE(message(s.o, p).find("samples per pixel"), std::string::npos);
    p = {};
    p.maxBounces = -1;
    EXPECT_NE(message(s.o, p).find("max bounces"), std::string::npos);
    p = {};
    ShadeOptions o = s.o;
    o.sunDirection = {std::nanf(""), 1.0f, 0.0f};
    EXPECT_NE(message(o, p).find("sun direction must be finite and non-zero, got (nan"),
              std::string::npos);
    o = s.o;
    o.sunDirection = {0.0f, 0.0f, 0.0f};
    EXPECT_NE(message(o, p).find("sun direction"), std::string::npos);
    o = s.o;
    o.skyTop = Rgb(-1.0f);
    EXPECT_NE(message(o, p).find("sky top must be finite and >= 0"), std::string::npos);
    o = s.o;
    o.sunIrradiance = Rgb(std::numeric_limits<float>::infinity());
    EXPECT_NE(message(o, p).find("sun irradiance"), std::string::npos);

    auto tracer = PathTracer::create(s.world, s.camera, s.o, {});
    ASSERT_TRUE(tracer.ok());
    EXPECT_FALSE(tracer->addSamples(0).ok());
    EXPECT_FALSE(tracer->addSamples(kMaxPathSamples + 1).ok());
}

}  // namespace
