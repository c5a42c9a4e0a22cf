// The real-time voxel solvers (sky visibility, radiance cascades) shade the visible surface with
// the path tracer's material model: on an open plane of rough metal or of the default rough
// dielectric under a constant sky and a sun in the mirror direction of the view (the highlight
// in view), their pictures match the path tracer's, which a Lambertian picture does not; the
// GGX directional albedo table is the integral of the path tracer's GGX lobe; glass shows what lies
// behind it as in the path tracer.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/sky_visibility.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/solver_surface.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

Rgb imageMean(const Image& image) {
    double sum[3] = {0, 0, 0};
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < 3; ++c) sum[c] += image.at(x, y, c);
    const double n = double(image.width()) * image.height();
    return Rgb(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
}

// The standard error of the image mean from the per-pixel standard errors.
double meanStandardError(const Image& se, int c) {
    double sum = 0;
    for (int y = 0; y < se.height(); ++y)
        for (int x = 0; x < se.width(); ++x) sum += double(se.at(x, y, c)) * se.at(x, y, c);
    return std::sqrt(sum) / (double(se.width()) * se.height());
}

Material roughMetal() {
    Material m;
    m.name = "metal";
    m.metallic = 1.0f;
    m.roughness = 0.5f;
    m.albedo = Rgb(0.9f, 0.6f, 0.3f);
    return m;
}

Material roughDielectric() {  // the default material of plain blocks, greyed
    Material m = defaultMaterial();
    m.name = "dielectric";
    m.albedo = Rgb(0.7f);
    return m;
}

struct PlaneScene {
    VoxelWorld world = floorWorld();
    ShadeOptions o;
    Camera camera;
    explicit PlaneScene(const Material& m)
        : camera(*Camera::create({16.0, 1.6, 12.0}, 0.0, -35.0, 20.0, 16, 12)) {
        o.textures = false;
        o.skyTop = o.skyHorizon = Rgb(0.8f, 0.9f, 1.0f);
        // The sun in the mirror direction of the view's centre: the highlight fills the picture.
        const Vec3d d = camera.rayAt(8.0, 6.0).direction;
        o.sunDirection = Vec3(float(d.x), float(-d.y), float(d.z));
        o.sunIrradiance = Rgb(3.0f);
        o.sunAngularRadius = 0.0;
        EXPECT_TRUE(o.materials.setPlain(m).ok());
    }
};

void expectMatchesThePathTracer(const Material& m) {
    const PlaneScene s(m);
    PathTraceOptions p;
    p.samplesPerPixel = 512;
    auto reference = pathTrace(s.world, s.camera, s.o, p);
    ASSERT_TRUE(reference.ok());
    const Rgb want = imageMean(reference->radiance);

    SkyVisibilityOptions ao;
    ao.rays = 64;
    auto sky = renderSkyVisibility(s.world, s.camera, s.o, ao);
    ASSERT_TRUE(sky.ok());
    auto cascades = RadianceCascades::create(s.world, nullptr, s.o, CascadeOptions{});
    ASSERT_TRUE(cascades.ok());
    cascades->solve();
    auto rc = cascades->render(s.camera);
    ASSERT_TRUE(rc.ok());
    const Rgb gotAo = imageMean(sky->radiance), gotRc = imageMean(*rc);
    // The picture of before, every material Lambertian of its colour: albedo x (sky + E cos / pi).
    const double cosSun = s.o.sunDirection.y / length(s.o.sunDirection);
    const double skyLight[3] = {0.8, 0.9, 1.0};
    for (int c = 0; c < 3; ++c) {
        // 3% (the directional albedo table, the sun's cosine at pixel centres) plus the path
        // tracer's noise; the Lambertian picture is further off than that.
        const double bound = 0.03 * want[c] + 4.0 * meanStandardError(reference->standardError, c);
        const double lambertian = m.albedo[c] * (skyLight[c] + 3.0 * cosSun / 3.14159265358979);
        EXPECT_GT(std::abs(lambertian - want[c]), bound) << m.name << ", channel " << c;
        EXPECT_NEAR(gotAo[c], want[c], bound) << m.name << " sky visibility, channel " << c;
        EXPECT_NEAR(gotRc[c], want[c], bound) << m.name << " radiance cascades, channel " << c;
    }
}

TEST(SolverMaterials, RoughMetalPlaneMatchesThePathTracer) {
    expectMatchesThePathTracer(roughMetal());
}

TEST(SolverMaterials, RoughDielectricPlaneMatchesThePathTracer) {
    expectMatchesThePathTracer(roughDielectric());
}

// A glowing wall (z = 0) seen along -z through a clear glass slab three voxels thick that fills
// the world's cross-section, the sky black: both solvers follow the refracted ray through the
// slab and show the wall with (1 - F)^2 t / (1 - F^2 t^2), the path tracer's answer
// (PathTraceMaterials.GlassSlabPassesTheFresnelSeriesAndBeerLambert); shaded as an opaque
// Lambertian face the glass would show its own colour times the light it receives.
TEST(SolverMaterials, GlassSlabShowsWhatLiesBehindIt) {
    const VoxelWorld world = slabBeforeAWall();
    ShadeOptions o;
    o.textures = false;
    o.sunIrradiance = Rgb(0.0f);
    o.skyTop = o.skyHorizon = Rgb(0.0f);
    Material glass;
    glass.name = "glass";
    glass.roughness = 0.0f;
    glass.transmission = 1.0f;
    glass.absorption = Rgb(0.2f);
    ASSERT_TRUE(o.materials.setSlot(0, glass).ok());
    Material wall;
    wall.name = "wall";
    wall.albedo = Rgb(0.0f);
    wall.emission = Rgb(2.0f);
    ASSERT_TRUE(o.materials.setSlot(1, wall).ok());
    const double f = 0.04, t = std::exp(-0.2 * 3.0);  // normal incidence, ior 1.5
    const double expected = 2.0 * (1 - f) * (1 - f) * t / (1 - f * f * t * t);

    const Camera camera = *Camera::create({4.3, 4.6, 14.0}, 180.0, 0.0, 4.0, 4, 4);
    auto sky = renderSkyVisibility(world, camera, o, SkyVisibilityOptions{});
    ASSERT_TRUE(sky.ok());
    auto cascades = RadianceCascades::create(world, nullptr, o, CascadeOptions{});
    ASSERT_TRUE(cascades.ok());
    cascades->solve();
    auto rc = cascades->render(camera);
    ASSERT_TRUE(rc.ok());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            EXPECT_NEAR(sky->radiance.at(x, y, 0), expected, 0.005 * expected) << x << "," << y;
            EXPECT_NEAR(rc->at(x, y, 0), expected, 0.005 * expected) << x << "," << y;
        }
}

// The integral over the hemisphere of the path tracer's GGX reflectance x cos (bsdfLight of a
// GGX-only lobe of reflectance 1), by the midpoint rule in (theta, phi): an evaluation, where the
// table comes from the path tracer's sampling.
double integratedAlbedo(double cosView, double alpha) {
    constexpr double kPi = 3.14159265358979323846;
    const PathBsdf b = ggxOnlyLobe(cosView, alpha);
    const int nt = 600, np = 600;
    double sum = 0.0;
    for (int i = 0; i < nt; ++i) {
        const double theta = (i + 0.5) / nt * (kPi / 2);
        for (int k = 0; k < np; ++k) {
            const double phi = (k + 0.5) / np * (2 * kPi);
            const Vec3d l{std::sin(theta) * std::cos(phi), std::cos(theta),
                          std::sin(theta) * std::sin(phi)};
            sum += bsdfLight(b, l, Rgb(1.0f), 0.0).r * std::sin(theta);
        }
    }
    return sum * (kPi / 2 / nt) * (2 * kPi / np);
}

TEST(SolverMaterials, GgxDirectionalAlbedoIsTheLobesIntegral) {
    // A near-mirror loses nothing to masking.
    EXPECT_NEAR(directionalAlbedoGgx(1.0, 0.0), 1.0, 0.01);
    EXPECT_NEAR(directionalAlbedoGgx(0.5, 0.0), 1.0, 0.01);
    for (const double cosView : {0.2, 0.5, 0.9}) {
        for (const double alpha : {0.2, 0.49, 0.8}) {
            const double want = integratedAlbedo(cosView, alpha);
            EXPECT_NEAR(directionalAlbedoGgx(cosView, alpha), want, 0.01)
                << "cos " << cosView << " alpha " << alpha;
            EXPECT_LT(want, 1.0);
        }
        // Rougher lobes lose more (single scattering).
        EXPECT_GT(directionalAlbedoGgx(cosView, 0.2), directionalAlbedoGgx(cosView, 0.8));
    }
}

}  // namespace
