// The voxel path tracer's materials against analytic answers: a mirror floor shows albedo x sky,
// a clear glass slab passes (1 - F)^2 / (1 - F^2) of what lies behind it (times Beer-Lambert's
// factor with absorption), a ray inside glass past the critical angle reflects totally, white
// furnaces of metal, glass and rough dielectric keep the sky's radiance within GGX's
// single-scattering loss, and images stay bit-identical for any thread count and pass split.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "gpu/shaders/shared/optics.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/path_trace.h"
#include "voxel/path_ray_estimate.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr double kPi = 3.14159265358979323846;

PathTraceOptions deepPaths() {
    PathTraceOptions p;
    p.maxBounces = kMaxPathBounces;
    p.rouletteAfter = kMaxPathBounces;
    return p;
}

TEST(PathTraceMaterials, MirrorFloorShowsAlbedoTimesSky) {
    const VoxelWorld world = floorWorld();
    const float sky = 1.5f;
    ShadeOptions o = plainLight(1.0f, Rgb(0.0f), Rgb(sky));
    const Rgb albedo(0.9f, 0.6f, 0.3f);
    ASSERT_TRUE(o.materials.setPlain(metal(0.0f, albedo)).ok());
    auto camera = Camera::create({16.0, 1.5, 16.0}, 0.0, -90.0, 20.0, 8, 8);
    ASSERT_TRUE(camera.ok());
    PathTraceOptions p;
    p.samplesPerPixel = 4;
    auto image = pathTrace(world, *camera, o, p);
    ASSERT_TRUE(image.ok());
    // Seen from above the metal's reflectance is its colour (Schlick's (1 - cos)^5 < 1e-9 within
    // 10 degrees of the normal); a delta mirror has no noise.
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(image->radiance.at(x, y, c), albedo[c] * sky, 1e-5) << x << "," << y;
                EXPECT_EQ(image->standardError.at(x, y, c), 0.0f);
            }
}

// Glowing wall (z = 0), a glass slab (z in [6, 9), filling the world's cross-section) and the
// camera at z = 14 looking at the wall through it along -z; the sky is black.
struct SlabScene {
    VoxelWorld world = slabBeforeAWall();
    ShadeOptions o = plainLight(0.0f, Rgb(0.0f), Rgb(0.0f));
    float emission = 2.0f;
    explicit SlabScene(Rgb absorption) {
        EXPECT_TRUE(o.materials.setSlot(0, glass(absorption)).ok());
        Material wall;
        wall.name = "wall";
        wall.albedo = Rgb(0.0f);
        wall.emission = Rgb(emission);
        EXPECT_TRUE(o.materials.setSlot(1, wall).ok());
    }
};

TEST(PathTraceMaterials, GlassSlabPassesTheFresnelSeriesAndBeerLambert) {
    const Ray ray{{4.3, 4.6, 14.0}, {0.0, 0.0, -1.0}};
    const double f = gpu::shared::fresnelDielectricExact(1.0f, 1.0f, 1.5f);  // 0.04
    EXPECT_NEAR(f, 0.04, 1e-6);
    const int n = 20000;
    for (const float sigma : {0.0f, 0.2f}) {
        const SlabScene s{Rgb(sigma)};
        const double t = std::exp(-sigma * 3.0);  // three voxels of glass
        // Light crossing the slab: (1 - F)^2 t sum_k (F^2 t^2)^k.
        const double expected = s.emission * (1 - f) * (1 - f) * t / (1 - f * f * t * t);
        const Estimate e = traceRay(s.world, ray, s.o, deepPaths(), n);
        EXPECT_GT(e.standardError, 0.0);
        EXPECT_NEAR(e.mean, expected, 4.0 * e.standardError) << "sigma " << sigma;
        // Not the opaque or single-interface answers.
        EXPECT_GT(std::abs(e.mean - s.emission * (1 - f) * t), 8.0 * e.standardError);
    }
}

TEST(PathTraceMaterials, RayInsideGlassPastTheCriticalAngleReflectsTotally) {
    // A glass bar two voxels wide (x in [10, 12), y in [2, 10), all z) over a glowing strip of
    // floor under it (x in [8, 14)), the sky black. A ray entering the top at 60 degrees refracts
    // to 35.3 degrees and meets the sides at 54.7 degrees, past the critical 41.8: it reflects
    // totally back and forth until it leaves through the bottom to the floor. Every inner face is
    // met at 35.3 degrees, where the Fresnel reflectance equals the entry's F, so the floor is seen
    // with (1 - F)^2 / (1 - F^2).
    VoxelWorld world = makeWorld({24, 14, 8});
    for (int z = 0; z < 8; ++z) {
        for (int x = 8; x < 14; ++x) world.set(x, 0, z, Voxel{255, 255, 255, 2});
        for (int y = 2; y < 10; ++y)
            for (int x = 10; x < 12; ++x) world.set(x, y, z, Voxel{255, 255, 255, 1});
    }
    world.refreshEmptySpace();
    ShadeOptions o = plainLight(0.0f, Rgb(0.0f), Rgb(0.0f));
    ASSERT_TRUE(o.materials.setSlot(0, glass()).ok());
    Material floor;
    floor.name = "floor";
    floor.albedo = Rgb(0.0f);
    floor.emission = Rgb(1.0f);
    ASSERT_TRUE(o.materials.setSlot(1, floor).ok());
    const double s60 = std::sin(kPi / 3), c60 = std::cos(kPi / 3);
    const Vec3d d{s60, -c60, 0.0};
    const Ray ray{Vec3d{10.3, 10.0, 4.5} - d * 2.0, d};
    const double f = gpu::shared::fresnelDielectricExact(float(c60), 1.0f, 1.5f);
    const double sinInside = s60 / 1.5;
    EXPECT_GT(std::sqrt(1 - sinInside * sinInside), 1 / 1.5);  // the sides: past critical
    const Estimate e = traceRay(world, ray, o, deepPaths(), 20000);
    EXPECT_NEAR(e.mean, (1 - f) * (1 - f) / (1 - f * f), 4.0 * e.standardError + 1e-6);
    // (1 - F) / (1 + F) = 0.832; rays refracted out of the sides would miss the strip.
    EXPECT_GT(e.mean, 0.8);
}

// Energy: pillars and a floor under a uniform sky S, every material of albedo 1. Glass loses
// nothing (every path ends in the sky with weight 1); GGX loses what single scattering loses,
// 1 - E(mu) per reflection, with E(mu) = int D Vis cos dw its directional albedo (computed here
// by quadrature).
double ggxAlbedo(double alpha, double mu) {
    const int steps = 400;
    double sum = 0.0;
    const double sinV = std::sqrt(1 - mu * mu);
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) / steps * kPi / 2;
        for (int j = 0; j < steps; ++j) {
            const double phi = (j + 0.5) / steps * 2 * kPi;
            const double lx = std::sin(theta) * std::cos(phi), ly = std::sin(theta) * std::sin(phi);
            const double lz = std::cos(theta);
            const double hx = lx + sinV, hy = ly, hz = lz + mu;
            const double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
            const double d = gpu::shared::ggxD(float(hz / hl), float(alpha));
            const double vis = gpu::shared::ggxSmithVisibility(float(mu), float(lz), float(alpha));
            sum += d * vis * lz * std::sin(theta) * (kPi / 2 / steps) * (2 * kPi / steps);
        }
    }
    return sum;
}

TEST(PathTraceMaterials, WhiteFurnacesKeepTheSkyWithinSingleScatteringLoss) {
    VoxelWorld world = makeWorld({24, 12, 24});
    for (int z = 0; z < 24; ++z)
        for (int x = 0; x < 24; ++x) {
            world.set(x, 0, z, kWhite);
            if (x % 6 == 2 && z % 5 == 1)
                for (int y = 1; y < 10; ++y) world.set(x, y, z, kWhite);
        }
    world.refreshEmptySpace();
    const float sky = 2.0f;
    auto camera = Camera::lookAt({1.0, 8.0, 1.0}, {14.0, 1.0, 14.0}, 60.0, 12, 8);
    ASSERT_TRUE(camera.ok());
    PathTraceOptions p = deepPaths();
    p.samplesPerPixel = 64;
    const double alpha = 0.25;  // roughness 0.5
    // GGX's directional albedo at roughness 0.5: 1 seen from above down to its grazing low.
    const double eAbove = ggxAlbedo(alpha, 1.0), eGrazing = ggxAlbedo(alpha, 0.1);
    EXPECT_GT(eAbove, 0.9);  // 0.9158 (a Python quadrature of 4000 steps agrees to 1e-5)
    EXPECT_LT(eGrazing, eAbove);
    // A rough dielectric loses F(mu) (1 - E(mu)) per reflection, Fresnel picking the GGX lobe.
    double dielectricLoss = 0.0;
    for (int i = 1; i <= 10; ++i) {
        const double mu = 0.1 * i;
        const double f = gpu::shared::fresnelDielectricExact(float(mu), 1.0f, 1.5f);
        dielectricLoss = std::max(dielectricLoss, f * (1.0 - ggxAlbedo(alpha, mu)));
    }
    Material rough;
    rough.name = "rough";
    rough.roughness = 0.5f;
    struct Case {
        Material material;
        double lowest;  // the image mean's lower bound, in units of the sky
    };
    // Metal: every reflection GGX, paths mostly of one or two reflections: at least E_grazing^2.
    // Rough dielectric: at most dielectricLoss per reflection, again one or two reflections.
    const Case cases[] = {{metal(0.5f, Rgb(1.0f)), eGrazing * eGrazing},
                          {glass(), 1.0 - 1e-6},
                          {rough, 1.0 - 2.0 * dielectricLoss}};
    for (const Case& c : cases) {
        ShadeOptions o = plainLight(1.0f, Rgb(0.0f), Rgb(sky));
        ASSERT_TRUE(o.materials.setPlain(c.material).ok());
        auto image = pathTrace(world, *camera, o, p);
        ASSERT_TRUE(image.ok());
        double mean = 0.0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 12; ++x) {
                const double l = image->radiance.at(x, y, 0);
                EXPECT_LE(l, sky + 4.0 * image->standardError.at(x, y, 0) + 1e-5)
                    << c.material.name << " " << x << "," << y;
                mean += l / 96.0;
            }
        std::printf("%s: image mean %.5f of the sky (bound %.5f)\n", c.material.name.c_str(),
                    mean / sky, c.lowest);
        EXPECT_GE(mean, sky * c.lowest) << c.material.name;
        EXPECT_LE(mean, sky * (1.0 + 1e-5)) << c.material.name;
    }
    // A rough metal plane under the sky reflects S E(mu): the tracer's GGX sampling against the
    // quadrature of the BRDF (one reflection; what leaves below the face is lost).
    const VoxelWorld plane = floorWorld();
    ShadeOptions o = plainLight(1.0f, Rgb(0.0f), Rgb(sky));
    ASSERT_TRUE(o.materials.setPlain(metal(0.5f, Rgb(1.0f))).ok());
    for (const double mu : {1.0, 0.5, 0.2}) {
        const Vec3d d{std::sqrt(1 - mu * mu), -mu, 0.0};
        const Estimate e = traceRay(plane, {Vec3d{16.2, 1.0, 16.3} - d, d}, o, deepPaths(), 8000);
        EXPECT_NEAR(e.mean, sky * ggxAlbedo(alpha, mu), 4.0 * e.standardError + 1e-4)
            << "mu " << mu;
    }
}

TEST(PathTraceMaterials, SunHighlightIsTheGgxLobeWithAndWithoutTheDisk) {
    // A rough metal plane (roughness 0.5, F = 1) under a black sky lit by the sun at 40 degrees
    // from the normal, seen at 30 degrees from the mirror direction's side: the radiance is
    // D(h) Vis cos_l E. A delta sun gives it with no noise; a 2-degree disk, sampled by light
    // samples and bounce rays weighted by the power heuristic, gives its mean over the disk.
    const VoxelWorld plane = floorWorld();
    ShadeOptions o = plainLight(1.0f, Rgb(0.0f), Rgb(0.0f));
    ASSERT_TRUE(o.materials.setPlain(metal(0.5f, Rgb(1.0f))).ok());
    const double sunAngle = 40.0 * kPi / 180, viewAngle = 30.0 * kPi / 180;
    const Vec3d l{std::sin(sunAngle), std::cos(sunAngle), 0.0};
    const Vec3d v{-std::sin(viewAngle) * 0.8, std::cos(viewAngle), std::sin(viewAngle) * 0.6};
    o.sunDirection = {float(l.x), float(l.y), float(l.z)};
    o.sunIrradiance = Rgb(2.0f);
    const Vec3d h = normalize(l + v);
    const double alpha = 0.25;
    const double expected = 2.0 * gpu::shared::ggxD(float(h.y), float(alpha)) *
                            gpu::shared::ggxSmithVisibility(float(v.y), float(l.y), float(alpha)) *
                            l.y;
    const Ray ray{Vec3d{16.2, 1.0, 16.3} + v, -v};
    PathTraceOptions p;
    p.maxBounces = 1;
    o.sunAngularRadius = 0.0;
    const Estimate delta = traceRay(plane, ray, o, p, 16);
    EXPECT_NEAR(delta.mean, expected, 1e-4 * expected);
    EXPECT_EQ(delta.standardError, 0.0);
    o.sunAngularRadius = 2.0 * kPi / 180;
    const Estimate disk = traceRay(plane, ray, o, p, 20000);
    EXPECT_GT(disk.standardError, 0.0);
    EXPECT_NEAR(disk.mean, expected, 4.0 * disk.standardError + 0.01 * expected);
}

bool sameImage(const Image& a, const Image& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(PathTraceMaterials, SameImageForAnyThreadCountAndPassSplit) {
    // Glass, amber, rough metal and a lamp over a default (rough dielectric) floor, the sun a
    // disk: every kind of vertex and random number.
    VoxelWorld world = makeWorld({16, 8, 16});
    for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) world.set(x, 0, z, Voxel{200, 180, 150, 255});
    for (int y = 1; y < 4; ++y)
        for (int x = 4; x < 7; ++x) {
            world.set(x, y, 6, Voxel{255, 255, 255, 1});
            world.set(x + 5, y, 8, Voxel{200, 200, 220, 2});
        }
    world.set(8, 1, 3, Voxel{255, 255, 255, 3});
    world.refreshEmptySpace();
    ShadeOptions o;
    o.sunDirection = {0.3f, 1.0f, 0.6f};
    o.sunAngularRadius = 0.05;
    ASSERT_TRUE(o.materials.setSlot(0, glass(Rgb(0.1f, 0.2f, 0.3f))).ok());
    ASSERT_TRUE(o.materials.setSlot(1, metal(0.3f, Rgb(0.9f))).ok());
    const Material lamp = lampMaterial(Rgb(4.0f));
    ASSERT_TRUE(o.materials.setSlot(2, lamp).ok());
    auto camera = Camera::lookAt({2.0, 5.0, 1.0}, {8.0, 1.0, 8.0}, 60.0, 16, 12);
    ASSERT_TRUE(camera.ok());
    PathTraceOptions p;
    p.samplesPerPixel = 6;
    PathTraceImage one, two;
    {
        ThreadLimit limit(1);
        one = *pathTrace(world, *camera, o, p);
    }
    {
        ThreadLimit limit(2);
        two = *pathTrace(world, *camera, o, p);
    }
    EXPECT_TRUE(sameImage(one.radiance, two.radiance));
    auto tracer = PathTracer::create(world, *camera, o, p);
    ASSERT_TRUE(tracer.ok());
    ASSERT_TRUE(tracer->addSamples(2).ok());
    ASSERT_TRUE(tracer->addSamples(4).ok());
    EXPECT_TRUE(sameImage(tracer->image().radiance, one.radiance));
    EXPECT_TRUE(sameImage(tracer->image().standardError, one.standardError));
}

}  // namespace
