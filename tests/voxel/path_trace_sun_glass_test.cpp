// The path tracer's sun light through glass (PathTraceOptions::sunThroughGlass): a floor under a
// glass pane receives the sun times the pane's two Fresnel transmissions and Beer-Lambert's
// factor, with the noise of direct light (bounce rays alone, which must happen to meet the
// sun's disk, leave fireflies); with a wide sun the two strategies' weights still sum to one,
// so the mean is what bounce rays alone give.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/shaders/shared/optics.h"
#include "luxel/voxel/path_trace.h"
#include "voxel/path_ray_estimate.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr double kPi = 3.14159265358979323846;

// A white floor (y = 0, albedo `albedo`, Lambertian) under a clear glass pane one voxel thick
// (y = 5, texture slot 0) that covers the whole world, a black sky and the sun of irradiance 1.
struct PaneScene {
    VoxelWorld world = paneOverAFloor();
    ShadeOptions o = plainLight(0.8f, Rgb(0.0f), Rgb(0.0f));
    explicit PaneScene(float sigma, Vec3 sun, double sunRadius) {
        EXPECT_TRUE(o.materials.setSlot(0, glass(Rgb(sigma))).ok());
        o.sunIrradiance = Rgb(1.0f);
        o.sunDirection = sun;
        o.sunAngularRadius = sunRadius;
    }
};

// Straight down onto the floor's centre, from between the floor and the pane.
const Ray kDown{{12.3, 3.0, 12.4}, {0.0, -1.0, 0.0}};

TEST(PathTraceSunThroughGlass, PaneOverAFloorPassesTheSunAsDirectLight) {
    const Vec3 sun{0.3f, 1.0f, 0.2f};
    const double cosSun = 1.0 / std::sqrt(0.09 + 1.0 + 0.04);
    const double f = gpu::shared::fresnelDielectricExact(float(cosSun), 1.0f, 1.5f);
    const double sinInside = std::sqrt(1.0 - cosSun * cosSun) / 1.5;
    const double pathInside = 1.0 / std::sqrt(1.0 - sinInside * sinInside);  // one voxel
    // Three bounces: the floor, into the pane and out of it (no light reflected inside it, and
    // the floor's light that the pane sends back is not counted), so the answer is exact.
    PathTraceOptions p;
    p.maxBounces = 3;
    p.rouletteAfter = 3;
    const int n = 4000;
    for (const float sigma : {0.0f, 0.3f}) {
        const PaneScene s(sigma, sun, 0.0047);  // the real sun's angular radius
        const double expected =
            0.8 / kPi * cosSun * (1 - f) * (1 - f) * std::exp(-sigma * pathInside);
        const Estimate on = traceRay(s.world, kDown, s.o, p, n);
        EXPECT_NEAR(on.mean, expected, 4.0 * on.standardError + 1e-6 * expected)
            << "sigma " << sigma;
        EXPECT_LT(on.standardError, 0.01 * expected) << "sigma " << sigma;
        // Bounce rays alone meet a disk of 7e-5 sr a few times in a million: far from the answer
        // with these samples, or far noisier.
        PathTraceOptions off = p;
        off.sunThroughGlass = false;
        const Estimate bounce = traceRay(s.world, kDown, s.o, off, n);
        EXPECT_TRUE(std::abs(bounce.mean - expected) > 10.0 * on.standardError ||
                    bounce.standardError > 10.0 * on.standardError)
            << "sigma " << sigma << ": " << bounce.mean << " +- " << bounce.standardError;
    }
}

TEST(PathTraceSunThroughGlass, DeltaSunPassesAPaneWithParallelFaces) {
    const Vec3 sun{0.3f, 1.0f, 0.2f};
    const double cosSun = 1.0 / std::sqrt(0.09 + 1.0 + 0.04);
    const double f = gpu::shared::fresnelDielectricExact(float(cosSun), 1.0f, 1.5f);
    PathTraceOptions p;
    p.maxBounces = 3;
    p.rouletteAfter = 3;
    const PaneScene s(0.0f, sun, 0.0);
    const Estimate on = traceRay(s.world, kDown, s.o, p, 4000);
    EXPECT_NEAR(on.mean, 0.8 / kPi * cosSun * (1 - f) * (1 - f), 4.0 * on.standardError + 1e-6);
    // Bounce rays never meet a delta sun: without the chain the floor is dark.
    PathTraceOptions off = p;
    off.sunThroughGlass = false;
    EXPECT_EQ(traceRay(s.world, kDown, s.o, off, 200).mean, 0.0);
}

// A wide sun (0.25 rad) that bounce rays meet often, deep paths (light reflected inside the
// pane and between pane and floor): sun sampling through the pane and bounce rays share the
// paths by their weights, so the mean is that of bounce rays alone.
TEST(PathTraceSunThroughGlass, WideSunSameMeanAsBounceRaysAlone) {
    const PaneScene s(0.1f, {-0.4f, 1.0f, 0.3f}, 0.25);
    PathTraceOptions p;
    p.maxBounces = 12;
    p.rouletteAfter = 12;
    const int n = 60000;
    const Estimate on = traceRay(s.world, kDown, s.o, p, n);
    PathTraceOptions off = p;
    off.sunThroughGlass = false;
    const Estimate bounce = traceRay(s.world, kDown, s.o, off, n);
    const double se = std::hypot(on.standardError, bounce.standardError);
    EXPECT_NEAR(on.mean, bounce.mean, 4.0 * se);
    EXPECT_LT(se, 0.03 * bounce.mean);  // sharp enough to see a share counted twice or lost
    EXPECT_LT(on.standardError, 0.5 * bounce.standardError);
}

}  // namespace
