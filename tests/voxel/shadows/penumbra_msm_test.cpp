// The penumbra-sized moment filter on two slabs at different heights over a floor: its blocker
// search finds each slab's height, the penumbra it predicts widens with it, and its visibility is
// closer to the cone-sampled ground truth than the fixed filter's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "luxel/voxel/shadows/moment_map.h"
#include "luxel/voxel/shadows/shadow_metrics.h"
#include "luxel/voxel/shadows/sun_visibility.h"

namespace luxel::voxel {
namespace {

// Floor y = 0; a low slab at y = 4 over x in [6, 18) and a high slab at y = 20 over x in [28, 40),
// both over z in [8, 24).
VoxelWorld twoSlabs() {
    VoxelWorld world = std::move(VoxelWorld::create({48, 24, 32}, 8).value());
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 48; ++x) {
            world.set(x, 0, z, Voxel{120, 120, 120, 255});
            if (z < 8 || z >= 24) continue;
            if (x >= 6 && x < 18) world.set(x, 4, z, Voxel{200, 60, 60, 255});
            if (x >= 28 && x < 40) world.set(x, 20, z, Voxel{60, 60, 200, 255});
        }
    world.refreshEmptySpace();
    return world;
}

constexpr double kRadius = 4.0 * std::numbers::pi / 180.0;
const Vec3d kSun{0.15, 1.0, 0.1};

SunVisibility make(const VoxelWorld& world, ShadowMethod method, ShadowSettings::MsmFilter filter) {
    ShadowSettings s;
    s.method = method;
    s.exactSamples = 256;
    s.mapSize = 128;
    s.msmFilter = filter;
    return std::move(SunVisibility::build(world, nullptr, {kSun, kRadius}, s).value());
}

std::vector<float> floorImage(const SunVisibility& v) {
    std::vector<float> out;
    for (double z = 2.25; z < 30; z += 0.5)
        for (double x = 1.25; x < 47; x += 0.5)
            out.push_back(v.visibility({{x, 1.0, z}, {0, 1, 0}, 10.0}));
    return out;
}

TEST(MsmPenumbraFilter, BlockerDepthAndWidthGrowWithTheSlabsHeight) {
    const VoxelWorld world = twoSlabs();
    const SunVisibility v =
        make(world, ShadowMethod::Msm, ShadowSettings::MsmFilter::PenumbraSized);
    const MomentShadowMap& map = *v.momentMap();
    const ShadowSettings& s = v.settings();
    // Floor points under each slab's shadow (the sun leans towards +x, +z: shadows move to -x).
    const Vec3d l = normalize(kSun);
    auto under = [&](double x, double top) {
        const double h = top - 1.0;  // floor top at y = 1
        return Vec3d{x - l.x / l.y * h, 1.0 + s.normalOffset, 16.0 - l.z / l.y * h};
    };
    const MomentShadowMap::Penumbra low = map.penumbra(under(12.0, 5.0), s);
    const MomentShadowMap::Penumbra high = map.penumbra(under(34.0, 21.0), s);
    ASSERT_TRUE(low.blocked);
    ASSERT_TRUE(high.blocked);
    // Light-space distances from the floor to each slab's top: (top - 1) / |l|.y-scaled.
    EXPECT_NEAR(low.blockerDepth, 4.0 * l.y, 1.0);
    EXPECT_NEAR(high.blockerDepth, 20.0 * l.y, 2.0);
    EXPECT_GT(high.width, 3.0 * low.width);
    EXPECT_GT(high.halfWidthTexels, low.halfWidthTexels);
    // Open floor far from both slabs has no blocker.
    EXPECT_FALSE(map.penumbra({46.0, 1.0 + s.normalOffset, 2.0}, s).blocked);
}

TEST(MsmPenumbraFilter, IsCloserToTheConeSampledTruthThanTheFixedFilter) {
    const VoxelWorld world = twoSlabs();
    const std::vector<float> truth =
        floorImage(make(world, ShadowMethod::Exact, ShadowSettings::MsmFilter::Fixed));
    const ShadowErrors fixed = compareVisibility(
        floorImage(make(world, ShadowMethod::Msm, ShadowSettings::MsmFilter::Fixed)), truth);
    const ShadowErrors sized = compareVisibility(
        floorImage(make(world, ShadowMethod::Msm, ShadowSettings::MsmFilter::PenumbraSized)),
        truth);
    ASSERT_GT(fixed.penumbraPixels, 200);
    EXPECT_LT(sized.maePenumbra, 0.8 * fixed.maePenumbra)
        << "fixed " << fixed.maePenumbra << " penumbra-sized " << sized.maePenumbra;
    EXPECT_LT(sized.maeAll, fixed.maeAll);
}

}  // namespace
}  // namespace luxel::voxel
