// The transmission lobe's exits into the air (SolverLight::mediumAirExits, solver_surface.h;
// docs/algorithms/voxel-radiance-cascades.md §4.2, "Light reflected inside followed glass"): a
// ray refracted into a pane one voxel thick leaves it at the far face with 1 - R of its light and
// goes on inside with R, leaving next through the near face, then the far one again. Each exit
// taken adds the next term of that series and one ray; after the last, the light still inside is
// dropped.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gpu/shaders/shared/optics.h"
#include "voxel/shaded_pane.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

// The pane of paneOverAFloor (clear glass, no absorption) seen along `direction` from above, every
// ray leaving it bringing radiance 1, with at most `airExits` exits into the air.
ShadedPane shadePane(Vec3d direction, int airExits) {
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    EXPECT_TRUE(o.materials.setSlot(0, glass()).ok());
    o.fresnel = ShadeOptions::FresnelModel::Exact;
    return shadePaneTop(
        o, direction, 1, [](const Ray&) { return Rgb(1.0f); },
        [airExits](SolverLight& light) { light.mediumAirExits = airExits; }, PathRng(1, 0, 0));
}

TEST(SolverAirExits, EachExitTakenAddsTheNextTermOfTheSeries) {
    for (const double cosView : {0.95, 0.7, 0.4}) {
        const Vec3d d = normalize(Vec3d{std::sqrt(1.0 - cosView * cosView), -cosView, 0.2});
        const double cosIn = -d.y;
        // The pane's faces are parallel: R is the same at every interface, inside and out.
        const double r = gpu::shared::fresnelDielectricExact(float(cosIn), 1.0f, 1.5f);
        const double entered = 1.0 - r;  // the transmission lobe's weight
        const ShadedPane one = shadePane(d, 1), two = shadePane(d, 2), three = shadePane(d, 3);
        const ShadedPane all = shadePane(d, kMaxMediumExits);
        // One ray per exit taken, then the mirror's.
        EXPECT_EQ(one.rays.size(), 2u);
        EXPECT_EQ(two.rays.size(), 3u);
        EXPECT_EQ(three.rays.size(), 4u);
        EXPECT_GE(all.rays.size(), three.rays.size());
        // The first exit leaves downwards through the far face, the second upwards through the
        // near one, parallel to the mirror's ray.
        EXPECT_NEAR(one.rays[0].origin.y, 5.0, 1e-9);
        EXPECT_LT(one.rays[0].direction.y, 0.0);
        EXPECT_NEAR(two.rays[1].origin.y, 6.0, 1e-9);
        EXPECT_NEAR(two.rays[1].direction.y, -d.y, 1e-6);
        // The series: (1 - R) entered, times (1 - R) R^k at exit k + 1; the mirror adds R.
        const double tolerance = 1e-5;
        EXPECT_NEAR(one.radiance.r, r + entered * (1.0 - r), tolerance) << cosView;
        EXPECT_NEAR(two.radiance.r - one.radiance.r, entered * (1.0 - r) * r, tolerance);
        EXPECT_NEAR(three.radiance.r - two.radiance.r, entered * (1.0 - r) * r * r, tolerance);
        // Whatever is dropped is at most what was still inside: R^n of what entered.
        EXPECT_LE(all.radiance.r - one.radiance.r, entered * r + tolerance);
        EXPECT_GE(all.radiance.r, three.radiance.r - tolerance);
    }
}

// The default takes every exit up to kMaxMediumExits interfaces: sky visibility's picture and
// every caller that does not set it are as they were.
TEST(SolverAirExits, TheDefaultDropsNothing) {
    const Vec3d d = normalize(Vec3d{0.6, -0.7, 0.1});
    const ShadedPane byDefault = shadePane(d, SolverLight{}.mediumAirExits);
    const ShadedPane unlimited = shadePane(d, 1 << 20);
    EXPECT_EQ(byDefault.rays.size(), unlimited.rays.size());
    EXPECT_EQ(byDefault.radiance.r, unlimited.radiance.r);
    EXPECT_EQ(byDefault.radiance.g, unlimited.radiance.g);
    EXPECT_GT(byDefault.rays.size(), 3u);
}

}  // namespace
