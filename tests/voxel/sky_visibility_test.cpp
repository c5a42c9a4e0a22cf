// Sky visibility (ambient occlusion) against the path tracer's one-reflection estimate at the same
// surface points, an open plane (V = 1, albedo x sky exactly), the analytic view of the sky from
// the bottom of a square well, a closed well (V = 0), the radius, determinism and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "luxel/core/parallel.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/sky_visibility.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

constexpr double kPi = 3.14159265358979323846;
constexpr Voxel kWhite{255, 255, 255, 255};
constexpr Voxel kOrange{230, 140, 60, 255};

VoxelWorld makeWorld(Int3 size) {
    auto world = VoxelWorld::create(size, 8);
    EXPECT_TRUE(world.ok());
    return std::move(*world);
}

// Plain diffuse blocks of this albedo (Lambertian in the path tracer too: ior 1, no specular
// layer) under a sky from `horizon` to `top` and the given sun (a disk of the default radius).
ShadeOptions plainLight(float albedo, Rgb top, Rgb horizon, Rgb sun) {
    ShadeOptions o;
    o.textures = false;
    o.sunIrradiance = sun;
    o.sunDirection = {0.4f, 0.8f, 0.3f};
    o.skyTop = top;
    o.skyHorizon = horizon;
    Material m;
    m.name = "test";
    m.albedo = Rgb(albedo);
    m.ior = 1.0f;
    EXPECT_TRUE(o.materials.setPlain(m).ok());
    return o;
}

// A floor with a wall and a pillar: occlusion, sun shadows and the sky in one view.
struct CornerScene {
    VoxelWorld world = makeWorld({24, 10, 24});
    ShadeOptions o = plainLight(0.7f, Rgb(0.3f, 0.5f, 1.0f), Rgb(1.0f, 0.9f, 0.8f), Rgb(3.0f));
    Camera camera = *Camera::lookAt({20.0, 7.0, 20.0}, {8.0, 1.0, 8.0}, 70.0, 12, 9);
    CornerScene() {
        for (int z = 0; z < 24; ++z)
            for (int x = 0; x < 24; ++x) world.set(x, 0, z, kWhite);
        for (int y = 1; y < 7; ++y)
            for (int x = 0; x < 24; ++x) world.set(x, y, 4, kOrange);
        for (int y = 1; y < 5; ++y) world.set(10, y, 10, kWhite);
        world.refreshEmptySpace();
    }
};

SkyVisibilityImage render(const VoxelWorld& world, const Camera& camera, const ShadeOptions& o,
                          SkyVisibilityOptions options) {
    auto image = renderSkyVisibility(world, camera, o, options);
    EXPECT_TRUE(image.ok()) << image.error().message();
    return std::move(*image);
}

bool sameImage(const Image& a, const Image& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(SkyVisibility, InfiniteRadiusMatchesThePathTracersFirstReflection) {
    // The path tracer with one reflection along each pixel-centre ray is the ground truth: the
    // same primary point, sun term and sky; only the random directions differ.
    const CornerScene s;
    SkyVisibilityOptions options;
    options.rays = 1024;
    const SkyVisibilityImage ao = render(s.world, s.camera, s.o, options);
    PathTraceOptions p;
    p.maxBounces = 1;
    const int n = 1024;
    double aoSum = 0.0, pathSum = 0.0;
    for (int y = 0; y < s.camera.height(); ++y) {
        for (int x = 0; x < s.camera.width(); ++x) {
            const Ray ray = s.camera.rayAt(x + 0.5, y + 0.5);
            double sum[3] = {0, 0, 0}, squares[3] = {0, 0, 0};
            for (int k = 0; k < n; ++k) {
                PathRng rng(99, std::uint64_t(y) * s.camera.width() + x, std::uint64_t(k));
                const Rgb c = tracePath(s.world, nullptr, ray, s.o, p, rng);
                for (int i = 0; i < 3; ++i) sum[i] += c[i], squares[i] += double(c[i]) * c[i];
            }
            for (int i = 0; i < 3; ++i) {
                const double mean = sum[i] / n;
                const double se = std::sqrt(std::max(0.0, squares[i] / n - mean * mean) / n);
                // Both estimates draw the same distribution per ray: combined error sqrt(2) se.
                EXPECT_NEAR(ao.radiance.at(x, y, i), mean, 5.0 * std::sqrt(2.0) * se + 1e-5)
                    << "pixel " << x << "," << y << " channel " << i;
                aoSum += ao.radiance.at(x, y, i);
                pathSum += mean;
            }
        }
    }
    EXPECT_NEAR(aoSum, pathSum, 0.01 * pathSum);
    // The view shows occlusion: some pixel's visibility is well below 1.
    float lowest = 1.0f;
    for (std::size_t i = 0; i < ao.visibility.size(); ++i) {
        lowest = std::min(lowest, ao.visibility.data()[i]);
    }
    EXPECT_LT(lowest, 0.8f);
}

TEST(SkyVisibility, EmissiveVoxelsLightTheirSurroundingsAsInThePathTracer) {
    // A glowing panel in front of the wall: the rays that meet it carry its emission, so the floor
    // by it brightens, by as much on average as the path tracer's first reflection says.
    CornerScene s;
    for (int y = 1; y < 4; ++y)
        for (int x = 12; x < 16; ++x) s.world.set(x, y, 5, Voxel{255, 255, 255, 1});  // slot 0
    s.world.refreshEmptySpace();
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = Rgb(5.0f, 4.0f, 3.0f);
    ASSERT_TRUE(s.o.materials.setSlot(0, lamp).ok());
    SkyVisibilityOptions options;
    options.rays = 2048;
    const SkyVisibilityImage ao = render(s.world, s.camera, s.o, options);
    ShadeOptions dark = s.o;
    Material off = lamp;
    off.emission = Rgb(0.0f);
    ASSERT_TRUE(dark.materials.setSlot(0, off).ok());
    const SkyVisibilityImage unlit = render(s.world, s.camera, dark, options);

    const PathEmitters emitters = PathEmitters::find(s.world, s.o.materials);
    PathTraceOptions p;
    p.maxBounces = 1;
    const int n = 1024;
    double aoSum = 0.0, pathSum = 0.0, unlitSum = 0.0;
    for (int y = 0; y < s.camera.height(); ++y) {
        for (int x = 0; x < s.camera.width(); ++x) {
            const Ray ray = s.camera.rayAt(x + 0.5, y + 0.5);
            for (int k = 0; k < n; ++k) {
                PathRng rng(7, std::uint64_t(y) * s.camera.width() + x, std::uint64_t(k));
                const Rgb c = tracePath(s.world, nullptr, ray, s.o, p, rng, &emitters);
                pathSum += (double(c[0]) + c[1] + c[2]) / n;
            }
            for (int i = 0; i < 3; ++i) {
                aoSum += ao.radiance.at(x, y, i);
                unlitSum += unlit.radiance.at(x, y, i);
            }
        }
    }
    EXPECT_NEAR(aoSum, pathSum, 0.02 * pathSum);
    // The panel's light is a visible part of the image, not lost in the tolerance.
    EXPECT_GT(aoSum - unlitSum, 0.1 * unlitSum);
}

TEST(SkyVisibility, OpenPlaneSeesTheWholeSky) {
    VoxelWorld world = makeWorld({32, 2, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) world.set(x, 0, z, kWhite);
    world.refreshEmptySpace();
    const float a = 0.6f;
    const Rgb sky(0.8f, 1.0f, 1.5f);
    const ShadeOptions o = plainLight(a, sky, sky, Rgb(0.0f));
    const Camera camera = *Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 8, 8);
    for (double radius : {kInfinity, 1e-3, 3.0}) {
        SkyVisibilityOptions options;
        options.rays = 64;
        options.radius = radius;
        const SkyVisibilityImage image = render(world, camera, o, options);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                EXPECT_EQ(image.visibility.at(x, y, 0), 1.0f) << radius;
                for (int i = 0; i < 3; ++i) {
                    EXPECT_NEAR(image.radiance.at(x, y, i), a * sky[i], 1e-5 * sky[i]) << radius;
                }
            }
    }
}

// Solid ground y = 0..depth around a 1x1 hole (cells (4, 1..depth, 4)); `closed` caps it.
VoxelWorld well(int depth, bool closed) {
    VoxelWorld world = makeWorld({9, depth + 3, 9});
    for (int y = 0; y <= depth; ++y)
        for (int z = 0; z < 9; ++z)
            for (int x = 0; x < 9; ++x) {
                if (!(x == 4 && z == 4 && y >= 1)) world.set(x, y, z, kWhite);
            }
    if (closed) world.set(4, depth + 1, 4, kWhite);
    world.refreshEmptySpace();
    return world;
}

SkyVisibility atWellBottom(const VoxelWorld& world, int rays, double radius) {
    const ShadeOptions o = plainLight(0.5f, Rgb(1.0f), Rgb(1.0f), Rgb(0.0f));
    SkyVisibilityOptions options;
    options.rays = rays;
    options.radius = radius;
    PathRng rng(5, 0, 0);
    return estimateSkyVisibility(world, nullptr, {4.5, 1.0, 4.5}, {0, 1, 0}, o, options, rng);
}

// The cosine-weighted fraction of the hemisphere a point sees through a parallel centred square
// of side 1 at height d: four corner rectangles of the point-to-rectangle form factor.
double squareFormFactor(double d) {
    const double a = 0.5 / d, s = std::sqrt(1.0 + a * a);
    return 4.0 * (2.0 * a / s * std::atan(a / s)) / (2.0 * kPi);
}

TEST(SkyVisibility, WellBottomSeesTheOpeningsFormFactor) {
    const int rays = 40000;
    double previous = 1.0;
    for (int depth : {1, 2, 4, 8}) {
        const SkyVisibility v = atWellBottom(well(depth, false), rays, kInfinity);
        const double expected = squareFormFactor(depth);
        const double sigma = std::sqrt(expected * (1.0 - expected) / rays);
        EXPECT_NEAR(v.visibility, expected, 4.0 * sigma + 1e-3) << "depth " << depth;
        EXPECT_LT(v.visibility, previous) << "depth " << depth;
        // A uniform sky of 1: the sky light is V exactly.
        EXPECT_NEAR(v.skyLight.g, v.visibility, 1e-5);
        previous = v.visibility;
    }
    const SkyVisibility closed = atWellBottom(well(4, true), 1000, kInfinity);
    EXPECT_EQ(closed.visibility, 0.0);
    EXPECT_EQ(closed.skyLight.maxComponent(), 0.0f);
}

TEST(SkyVisibility, ShorterRadiusSeesMoreSky) {
    const VoxelWorld world = well(4, false);
    const double tiny = atWellBottom(world, 4000, 0.25).visibility;
    const double one = atWellBottom(world, 4000, 1.0).visibility;
    const double three = atWellBottom(world, 4000, 3.0).visibility;
    const double all = atWellBottom(world, 4000, kInfinity).visibility;
    EXPECT_EQ(tiny, 1.0);  // the walls are 0.5 voxel away, the floor is behind the face
    EXPECT_GT(tiny, one);
    EXPECT_GT(one, three);
    EXPECT_GT(three, all);
    // Even a closed well sees "sky" when the lid is out of reach.
    EXPECT_EQ(atWellBottom(well(4, true), 100, 0.25).visibility, 1.0);
}

TEST(SkyVisibility, SameSeedSameImageForAnyThreadCount) {
    const CornerScene s;
    SkyVisibilityOptions options;
    options.rays = 8;
    options.radius = 6.0;
    SkyVisibilityImage one, two;
    {
        ThreadLimit limit(1);
        one = render(s.world, s.camera, s.o, options);
    }
    {
        ThreadLimit limit(2);
        two = render(s.world, s.camera, s.o, options);
    }
    EXPECT_TRUE(sameImage(one.radiance, two.radiance));
    EXPECT_TRUE(sameImage(one.visibility, two.visibility));
    options.seed = 2;
    EXPECT_FALSE(sameImage(render(s.world, s.camera, s.o, options).radiance, one.radiance));
}

TEST(SkyVisibility, RefusesBadInputWithTheFieldNamed) {
    const CornerScene s;
    auto refused = [&](SkyVisibilityOptions options, ShadeOptions o, const std::string& field) {
        auto image = renderSkyVisibility(s.world, s.camera, o, options);
        ASSERT_FALSE(image.ok()) << field;
        EXPECT_NE(image.error().message().find(field), std::string::npos)
            << image.error().message();
    };
    SkyVisibilityOptions options;
    options.rays = 0;
    refused(options, s.o, "sky visibility rays must be in 1..");
    options.rays = kMaxSkyRays + 1;
    refused(options, s.o, "sky visibility rays must be in 1..");
    options.rays = 4;
    for (double radius : {0.0, -2.0, std::numeric_limits<double>::quiet_NaN()}) {
        options.radius = radius;
        refused(options, s.o, "sky visibility radius must be > 0");
    }
    options.radius = kInfinity;
    ShadeOptions o = s.o;
    o.skyTop = Rgb(std::numeric_limits<float>::quiet_NaN());
    refused(options, o, "sky top");
}

}  // namespace
