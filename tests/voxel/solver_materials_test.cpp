// The real-time voxel solvers (sky visibility, radiance cascades) shade the visible surface with
// the path tracer's material model: on an open plane of rough metal or of the default rough
// dielectric under a constant sky and a sun in the mirror direction of the view (the highlight
// in view), their pictures match the path tracer's, which a Lambertian picture does not; the
// GGX directional albedo table behaves as single scattering must.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/sky_visibility.h"
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
    for (int c = 0; c < 3; ++c) {
        // 3% (the directional albedo table, the sun's cosine at pixel centres) plus the path
        // tracer's noise; a Lambertian picture of the same colour is off by 20% or more here.
        const double bound = 0.03 * want[c] + 4.0 * meanStandardError(reference->standardError, c);
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

TEST(SolverMaterials, GgxDirectionalAlbedoIsSingleScattering) {
    // A near-mirror loses nothing; a rough lobe loses more the rougher and the more grazing.
    EXPECT_NEAR(directionalAlbedoGgx(1.0, 0.0), 1.0, 0.01);
    EXPECT_NEAR(directionalAlbedoGgx(0.5, 0.0), 1.0, 0.01);
    EXPECT_LT(directionalAlbedoGgx(1.0, 1.0), 0.85);
    EXPECT_GT(directionalAlbedoGgx(1.0, 1.0), 0.4);
    for (double alpha : {0.1, 0.3, 0.5, 0.7}) {
        EXPECT_GE(directionalAlbedoGgx(0.9, alpha), directionalAlbedoGgx(0.9, alpha + 0.2) - 1e-3)
            << alpha;
        EXPECT_GE(directionalAlbedoGgx(0.9, alpha), directionalAlbedoGgx(0.2, alpha) - 1e-3)
            << alpha;
    }
}

}  // namespace
