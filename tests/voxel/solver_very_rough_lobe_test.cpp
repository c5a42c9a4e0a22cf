// Very rough lobes take one ray (SolverLight::roughLobeOneRay, kSolverRoughAlpha,
// solver_surface.h; docs/algorithms/voxel-radiance-cascades.md §4.2, "Very rough lobes take one
// ray"): a surface whose GGX alpha is at least kSolverRoughAlpha asks for the light along one GGX
// direction where the radiance cascades' picture would cast two, and shades as with one; the
// default roughness (0.7, alpha 0.49) and sharper lobes, and callers that do not set it, keep
// every direction.
#include <gtest/gtest.h>

#include "voxel/shaded_pane.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

// The top of paneOverAFloor's pane, a metal of `roughness`, seen from nearly overhead (so that
// its GGX directions leave above the face), the light along each ray leaving it depending on its
// direction.
ShadedPane shadeRough(float roughness, int specularRays, bool roughOneRay) {
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    EXPECT_TRUE(o.materials.setSlot(0, metal(roughness, Rgb(0.9f, 0.8f, 0.7f))).ok());
    return shadePaneTop(
        o, normalize(Vec3d{0.1, -1.0, 0.05}), specularRays,
        [](const Ray& r) {
            return Rgb(float(1.0 + 3.0 * r.direction.x), 1.0f, float(1.0 + 5.0 * r.direction.z));
        },
        [roughOneRay](SolverLight& light) { light.roughLobeOneRay = roughOneRay; },
        PathRng(7, 3, 0));
}

TEST(SolverVeryRoughLobe, AVeryRoughLobeTakesOneDirection) {
    // Roughness 0.8 (the glass scene's stone): alpha 0.64, over kSolverRoughAlpha.
    const ShadedPane rough = shadeRough(0.8f, 2, true);
    const ShadedPane one = shadeRough(0.8f, 1, false);
    const ShadedPane two = shadeRough(0.8f, 2, false);
    ASSERT_EQ(rough.rays.size(), 1u);
    ASSERT_EQ(two.rays.size(), 2u);
    // The same direction as the first of two, and the same light as one ray asked for.
    EXPECT_EQ(rough.rays[0].direction.x, two.rays[0].direction.x);
    expectSameRgb(rough.radiance, one.radiance);
    EXPECT_NE(rough.radiance.r, two.radiance.r);
}

TEST(SolverVeryRoughLobe, TheDefaultRoughnessAndOtherCallersKeepEveryDirection) {
    // Roughness 0.7 (alpha 0.49, the default) and 0.3: the flag changes nothing.
    for (const float roughness : {0.7f, 0.3f}) {
        const ShadedPane flagged = shadeRough(roughness, 2, true);
        EXPECT_EQ(flagged.rays.size(), 2u) << roughness;
        expectSameRgb(flagged.radiance, shadeRough(roughness, 2, false).radiance);
    }
    // Not set (sky visibility, the default): a very rough lobe keeps its directions.
    EXPECT_FALSE(SolverLight{}.roughLobeOneRay);
    EXPECT_EQ(shadeRough(0.8f, 2, false).rays.size(), 2u);
}

}  // namespace
