// Sharp lobes take one ray (SolverLight::sharpLobeOneRay, kSolverSharpAlpha, solver_surface.h;
// docs/algorithms/voxel-radiance-cascades.md §4.2, "Sharp lobes take one ray"): a polished metal
// whose GGX alpha is at most kSolverSharpAlpha asks for the light along one GGX direction where
// the radiance cascades' picture would cast two, and shades as with one; rougher lobes, and
// callers that do not set it, keep every direction. A sharp lobe draws no light samples of the
// lamps ("Sharp lobes take no lamp samples"): its GGX direction counts the lamp it meets weighed
// against none.
#include <gtest/gtest.h>

#include <vector>

#include "voxel/shaded_pane.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

// The top of paneOverAFloor's pane, a metal of `roughness`, seen obliquely from above, the light
// along each ray leaving it depending on its direction.
ShadedPane shadeMetal(float roughness, int specularRays, bool sharpOneRay) {
    return shadePaneTop(
        metalPaneOptions(roughness), normalize(Vec3d{0.5, -0.8, 0.2}), specularRays,
        lightVaryingWithDirection,
        [sharpOneRay](SolverLight& light) { light.sharpLobeOneRay = sharpOneRay; },
        PathRng(7, 3, 0));
}

TEST(SolverSharpLobe, ASharpLobeTakesOneDirection) {
    // Roughness 0.03: alpha 0.0009, under kSolverSharpAlpha.
    const ShadedPane sharp = shadeMetal(0.03f, 2, true);
    const ShadedPane one = shadeMetal(0.03f, 1, false);
    const ShadedPane two = shadeMetal(0.03f, 2, false);
    ASSERT_EQ(sharp.rays.size(), 1u);
    EXPECT_EQ(two.rays.size(), 2u);
    // The same direction as the first of two, and the same light as one ray asked for.
    EXPECT_EQ(sharp.rays[0].direction.x, two.rays[0].direction.x);
    expectSameRgb(sharp.radiance, one.radiance);
    EXPECT_NE(sharp.radiance.r, two.radiance.r);
    // Two directions of so sharp a lobe lie within about a tenth of a degree: their mean light
    // is within 0.2% of one's.
    EXPECT_NEAR(sharp.radiance.r, two.radiance.r, 2e-3 * two.radiance.r);
}

TEST(SolverSharpLobe, RougherLobesAndOtherCallersKeepEveryDirection) {
    // Roughness 0.3 (alpha 0.09): the flag changes nothing.
    const ShadedPane rough = shadeMetal(0.3f, 2, true), roughBefore = shadeMetal(0.3f, 2, false);
    EXPECT_EQ(rough.rays.size(), 2u);
    expectSameRgb(rough.radiance, roughBefore.radiance);
    // Not set (sky visibility, the default): a sharp lobe keeps its directions.
    EXPECT_FALSE(SolverLight{}.sharpLobeOneRay);
    EXPECT_EQ(shadeMetal(0.03f, 4, false).rays.size(), 4u);
}

// The pane's top, a metal of `roughness`, whose GGX directions each meet a lamp (emission 5) that
// the light samples find with density `lightDensity`; `samples` counts the light samples drawn
// (each bringing 0.25).
Rgb shadeWithALamp(float roughness, double lightDensity, int* samples) {
    return shadePaneTop(
               metalPaneOptions(roughness), normalize(Vec3d{0.5, -0.8, 0.2}), 2,
               [](const Ray&) { return Rgb(1.0f); },
               [lightDensity, samples](SolverLight& light) {
                   light.sharpLobeOneRay = true;
                   light.glossyAlong = [lightDensity](const Ray&) {
                       return GlossyAlong{Rgb(1.0f), Rgb(5.0f), lightDensity};
                   };
                   light.glossyLamps = [samples](const PathBsdf&, int, PathRng&) {
                       ++*samples;
                       return Rgb(0.25f);
                   };
               },
               PathRng(7, 3, 0))
        .radiance;
}

TEST(SolverSharpLobe, ASharpLobeTakesNoLampSamples) {
    int samples = 0;
    // Roughness 0.03: no light sample drawn, and the lamp its direction meets weighed against
    // none, whatever their density would have been.
    const Rgb sparse = shadeWithALamp(0.03f, 1.0, &samples);
    const Rgb dense = shadeWithALamp(0.03f, 1000.0, &samples);
    EXPECT_EQ(samples, 0);
    expectSameRgb(sparse, dense);
    // Roughness 0.3: one light sample each, and a denser one leaves the GGX directions less.
    const Rgb roughSparse = shadeWithALamp(0.3f, 1.0, &samples);
    const Rgb roughDense = shadeWithALamp(0.3f, 1000.0, &samples);
    EXPECT_EQ(samples, 2);
    EXPECT_GT(roughSparse.r, roughDense.r);
}

}  // namespace
