// Very rough lobes take one ray (SolverLight::roughLobeOneRay, kSolverRoughAlpha,
// solver_surface.h; docs/algorithms/voxel-radiance-cascades.md §4.2, "Very rough lobes take one
// ray"): a surface whose GGX alpha is at least kSolverRoughAlpha (the default roughness 0.7,
// alpha 0.49, among them) asks for the light along one GGX direction where the radiance cascades'
// picture would cast two, and shades as with one; that direction's light is counted unbiased, its
// mean over many draws the lobe's integral; sharper lobes, and callers that do not set it, keep
// every direction.
#include <gtest/gtest.h>

#include <cmath>

#include "voxel/path_trace_bsdf.h"
#include "voxel/path_trace_surface.h"
#include "voxel/shaded_pane.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

// The top of paneOverAFloor's pane, a metal of `roughness`, seen from nearly overhead (so that
// its GGX directions leave above the face), the light along each ray leaving it depending on its
// direction.
ShadedPane shadeRough(float roughness, int specularRays, bool roughOneRay) {
    return shadePaneTop(
        metalPaneOptions(roughness), normalize(Vec3d{0.1, -1.0, 0.05}), specularRays,
        lightVaryingWithDirection,
        [roughOneRay](SolverLight& light) { light.roughLobeOneRay = roughOneRay; },
        PathRng(7, 3, 0));
}

TEST(SolverVeryRoughLobe, AVeryRoughLobeTakesOneDirection) {
    // Roughness 0.8 (the glass scene's stone, alpha 0.64) and 0.7 (the default, alpha 0.49): over
    // kSolverRoughAlpha.
    for (const float roughness : {0.8f, 0.7f}) {
        const ShadedPane rough = shadeRough(roughness, 2, true);
        const ShadedPane one = shadeRough(roughness, 1, false);
        const ShadedPane two = shadeRough(roughness, 2, false);
        ASSERT_EQ(rough.rays.size(), 1u) << roughness;
        ASSERT_EQ(two.rays.size(), 2u) << roughness;
        // The same direction as the first of two, and the same light as one ray asked for.
        EXPECT_EQ(rough.rays[0].direction.x, two.rays[0].direction.x) << roughness;
        expectSameRgb(rough.radiance, one.radiance);
        EXPECT_NE(rough.radiance.r, two.radiance.r) << roughness;
    }
}

TEST(SolverVeryRoughLobe, SharperLobesAndOtherCallersKeepEveryDirection) {
    // Roughness 0.6 (alpha 0.36) and 0.3: the flag changes nothing.
    for (const float roughness : {0.6f, 0.3f}) {
        const ShadedPane flagged = shadeRough(roughness, 2, true);
        EXPECT_EQ(flagged.rays.size(), 2u) << roughness;
        expectSameRgb(flagged.radiance, shadeRough(roughness, 2, false).radiance);
    }
    // Not set (sky visibility, the default): a very rough lobe keeps its directions.
    EXPECT_FALSE(SolverLight{}.roughLobeOneRay);
    EXPECT_EQ(shadeRough(0.8f, 2, false).rays.size(), 2u);
}

// The mean and the spread (standard deviation, red) over many pixels of the top of a metal pane
// of the default roughness, one GGX direction each, under `lightAlong` with the control variate
// E / pi = `variate` (a metal has no diffuse lobe that it would light).
struct OneDirection {
    Rgb mean;
    double spread = 0.0;
};
template <class Light>
OneDirection oneDirectionOver(const ShadeOptions& o, Vec3d direction, const Light& lightAlong,
                              float variate) {
    constexpr int kPixels = 20000;
    double mean[3] = {}, squares = 0.0;
    for (int i = 0; i < kPixels; ++i) {
        const ShadedPane pane = shadePaneTop(
            o, direction, 2, lightAlong,
            [variate](SolverLight& light) {
                light.roughLobeOneRay = true;
                light.diffuseRadiance = Rgb(variate);
            },
            PathRng(11, std::uint64_t(i), 0));
        EXPECT_LE(pane.rays.size(), 1u);  // none where the direction fell below the face
        for (int c = 0; c < 3; ++c) mean[c] += pane.radiance[c] / double(kPixels);
        squares += double(pane.radiance.r) * pane.radiance.r / double(kPixels);
    }
    return {Rgb(float(mean[0]), float(mean[1]), float(mean[2])),
            std::sqrt(squares - mean[0] * mean[0])};
}

TEST(SolverVeryRoughLobe, OneDirectionsMeanIsTheLobesLight) {
    // Grey light growing towards the horizon, where GGX's sampling weight w = G2 / G1 is
    // smallest: the mean of one direction, with no control variate and with one, against the
    // lobe's integral of f cos L over a fine grid of the hemisphere (bsdfLight, delta light).
    const auto lightAlong = [](const Ray& r) {
        const double up = 1.0 - r.direction.y;
        return Rgb(float(1.0 + 8.0 * up * up));
    };
    const ShadeOptions o = metalPaneOptions(0.7f);
    const Vec3d direction = normalize(Vec3d{0.6, -1.0, 0.2});
    const OneDirection plain = oneDirectionOver(o, direction, lightAlong, 0.0f);
    const OneDirection varied = oneDirectionOver(o, direction, lightAlong, 1.5f);
    // The lobe at the pane's top, as shadeSolverSurface makes it.
    const VoxelWorld world = paneOverAFloor();
    const SurfaceHit s =
        castToSurface(world, nullptr, {Vec3d{12.0, 7.5, 12.0} - direction, direction}, o.stepCap);
    const PathSurface surface = pathSurfaceAt(world, s, o);
    const PathBsdf b = pathBsdf(*surface.material, surface.albedo, s.hit.normal, direction, o);
    PathBsdf unit = specularLobe(b);
    unit.specular = Rgb(1.0f);
    unit.pSpecular = 1.0;
    // The integral of f cos L, and the split sum's answer for one direction: S A times the mean
    // of L over the directions GGX samples (its density, above the face).
    constexpr int kSteps = 600;
    constexpr double kPi = 3.14159265358979323846;
    double exact[3] = {0.0, 0.0, 0.0}, sampled = 0.0, density = 0.0;
    const double cell = (1.0 / kSteps) * (2.0 * kPi / kSteps);
    for (int i = 0; i < kSteps; ++i) {
        const double cosL = (i + 0.5) / kSteps, sinL = std::sqrt(1.0 - cosL * cosL);
        for (int j = 0; j < kSteps; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / kSteps;
            const Vec3d l{sinL * std::cos(phi), cosL, sinL * std::sin(phi)};
            const Rgb light = lightAlong({s.hit.point, l});
            const Rgb f = bsdfLight(b, l, light, 0.0);
            for (int c = 0; c < 3; ++c) exact[c] += f[c] * cell;
            const double p = ggxDensity(unit, l);
            sampled += p * light.r * cell;
            density += p * cell;
        }
    }
    const double albedo = directionalAlbedoGgx(b.cosView, b.alpha);
    for (int c = 0; c < 3; ++c) {
        const double splitSum = b.specular[c] * albedo * sampled / density;
        EXPECT_NEAR(plain.mean[c], exact[c], 0.01 * exact[c]) << c;
        EXPECT_NEAR(varied.mean[c], exact[c], 0.01 * exact[c]) << c;
        // What the test tells apart: the split sum's one direction is further off than that.
        EXPECT_GT(std::abs(splitSum - exact[c]), 0.04 * exact[c]) << c;
    }
}

TEST(SolverVeryRoughLobe, TheDiffuseLightNarrowsOneDirectionsSpread) {
    // Light that varies little (a sky), where the spread of one direction is mostly that of w:
    // E / pi near L takes it away, and the mean stays.
    const auto lightAlong = [](const Ray& r) { return Rgb(float(2.0 + 0.5 * r.direction.x)); };
    const ShadeOptions o = metalPaneOptions(0.7f);
    const Vec3d direction = normalize(Vec3d{0.6, -1.0, 0.2});
    const OneDirection plain = oneDirectionOver(o, direction, lightAlong, 0.0f);
    const OneDirection varied = oneDirectionOver(o, direction, lightAlong, 2.0f);
    EXPECT_LT(varied.spread, 0.5 * plain.spread);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(varied.mean[c], plain.mean[c], 0.01 * plain.mean[c]);
}

}  // namespace
