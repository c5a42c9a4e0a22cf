// Sun visibility by every method on a small roof-over-floor world, against the cone-sampled
// ground truth and against the analytic penumbra of a straight edge.
#include "luxel/voxel/shadows/sun_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "luxel/voxel/shadows/shadow_metrics.h"

namespace luxel::voxel {
namespace {

// A floor (y = 0) and a floating roof slab (y = 8) over x, z in [8, 24).
VoxelWorld roofWorld() {
    VoxelWorld world = std::move(VoxelWorld::create({32, 16, 32}, 8).value());
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) {
            world.set(x, 0, z, Voxel{120, 120, 120, 255});
            if (x >= 8 && x < 24 && z >= 8 && z < 24) world.set(x, 8, z, Voxel{200, 60, 60, 255});
        }
    world.refreshEmptySpace();
    return world;
}

constexpr double kRadius = 5.0 * std::numbers::pi / 180.0;

SunVisibility make(const VoxelWorld& world, ShadowMethod method, Vec3d sun = {0.3, 1.0, 0.2}) {
    ShadowSettings s;
    s.method = method;
    s.exactSamples = 256;
    s.mapSize = 128;
    return std::move(SunVisibility::build(world, nullptr, {sun, kRadius}, s).value());
}

// Visibility of the floor's top face on a grid of points.
std::vector<float> floorImage(const SunVisibility& v, double footprint = 10.0) {
    std::vector<float> out;
    for (double z = 2.25; z < 30; z += 0.5)
        for (double x = 2.25; x < 30; x += 0.5)
            out.push_back(v.visibility({{x, 1.0, z}, {0, 1, 0}, footprint}));
    return out;
}

TEST(SunVisibility, ExactMatchesTheDiskSegmentOfAStraightEdge) {
    // Sun straight up: the roof's x = 8 edge casts a penumbra on the floor whose visible part is
    // the disk segment beyond the edge: V = (acos(s) - s sqrt(1 - s^2)) / pi, s = offset / radius.
    const VoxelWorld world = roofWorld();
    const SunVisibility exact = make(world, ShadowMethod::Exact, {0.0, 1.0, 0.0});
    const double r = std::tan(kRadius) * 7.0;  // penumbra half-width at 7 voxels below the roof
    for (double x = 8.0 - 1.2 * r; x <= 8.0 + 1.2 * r; x += r / 4) {
        const double s = std::clamp((x - 8.0) / r, -1.0, 1.0);
        const double expected = (std::acos(s) - s * std::sqrt(1 - s * s)) / std::numbers::pi;
        EXPECT_NEAR(exact.visibility({{x, 1.0, 16.0}, {0, 1, 0}, 0.0}), expected, 0.04) << x;
    }
}

TEST(SunVisibility, EveryMethodAgreesAwayFromPenumbrae) {
    const VoxelWorld world = roofWorld();
    const std::vector<float> truth = floorImage(make(world, ShadowMethod::Exact));
    std::vector<std::uint8_t> clear(truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i) clear[i] = truth[i] == 0.0f || truth[i] == 1.0f;
    for (ShadowMethod m : {ShadowMethod::Hard, ShadowMethod::Msm, ShadowMethod::Vsm,
                           ShadowMethod::Sdf, ShadowMethod::Blend}) {
        const std::vector<float> est = floorImage(make(world, m));
        const ShadowErrors all = compareVisibility(est, truth);
        const ShadowErrors away = compareVisibility(est, truth, clear);
        SCOPED_TRACE(shadowMethodName(m));
        EXPECT_LT(all.maeAll, 0.05);
        EXPECT_LT(away.leakRate, 0.01);
        EXPECT_LT(away.falseShadowRate, 0.01);
        if (m != ShadowMethod::Hard) {
            EXPECT_LT(all.maePenumbra, 0.25);
        }
    }
}

TEST(SunVisibility, FacesTurnedAwayFromTheSunAreDark) {
    const VoxelWorld world = roofWorld();
    for (ShadowMethod m : {ShadowMethod::Hard, ShadowMethod::Exact, ShadowMethod::Msm,
                           ShadowMethod::Sdf, ShadowMethod::Blend, ShadowMethod::FloodFill}) {
        EXPECT_EQ(make(world, m).visibility({{4.0, 8.0, 4.0}, {0, -1, 0}, 1.0}), 0.0f);
    }
}

TEST(SunVisibility, FloodFillIsDarkerUnderTheRoof) {
    const VoxelWorld world = roofWorld();
    const SunVisibility flood = make(world, ShadowMethod::FloodFill);
    EXPECT_EQ(flood.visibility({{2.5, 1.0, 2.5}, {0, 1, 0}, 0.0}), 1.0f);
    // Under the middle of the roof the light has come 8 steps sideways and down from the edge.
    const float under = flood.visibility({{16.5, 1.0, 16.5}, {0, 1, 0}, 0.0});
    EXPECT_LT(under, 0.5f);
    EXPECT_GT(under, 0.0f);
}

TEST(SunVisibility, BlendIsTheSdfNearAndTheMsmFar) {
    const VoxelWorld world = roofWorld();
    const SunVisibility blend = make(world, ShadowMethod::Blend);
    const SunVisibility sdf = make(world, ShadowMethod::Sdf);
    const SunVisibility msm = make(world, ShadowMethod::Msm);
    const ShadowSettings& s = blend.settings();
    EXPECT_EQ(floorImage(blend, s.blendNear - 1), floorImage(sdf));
    EXPECT_EQ(floorImage(blend, s.blendFar + 1), floorImage(msm));
    const std::vector<float> mid = floorImage(blend, 0.5 * (s.blendNear + s.blendFar));
    const std::vector<float> a = floorImage(sdf), b = floorImage(msm);
    for (std::size_t i = 0; i < mid.size(); ++i) {
        ASSERT_GE(mid[i], std::min(a[i], b[i]) - 1e-6f);
        ASSERT_LE(mid[i], std::max(a[i], b[i]) + 1e-6f);
    }
}

TEST(SunVisibility, SixteenBitMomentsStayCloseToFp32) {
    const VoxelWorld world = roofWorld();
    ShadowSettings s;
    s.method = ShadowMethod::Msm;
    s.mapSize = 128;
    const SunVisibility fp32 =
        std::move(SunVisibility::build(world, nullptr, {{0.3, 1.0, 0.2}, kRadius}, s).value());
    s.momentStorage = ShadowSettings::MomentStorage::Quantized16;
    const SunVisibility q16 =
        std::move(SunVisibility::build(world, nullptr, {{0.3, 1.0, 0.2}, kRadius}, s).value());
    EXPECT_LT(compareVisibility(floorImage(q16), floorImage(fp32)).maeAll, 0.01);
}

TEST(SunVisibility, BadSettingsAreRefused) {
    const VoxelWorld world = roofWorld();
    ShadowSettings s;
    s.mapSize = 0;
    EXPECT_FALSE(SunVisibility::build(world, nullptr, {{0, 1, 0}, 0.01}, s));
    EXPECT_FALSE(SunVisibility::build(world, nullptr, {{0, 0, 0}, 0.01}, ShadowSettings{}));
    EXPECT_FALSE(SunVisibility::build(world, nullptr, {{0, 1, 0}, std::nan("")}, ShadowSettings{}));
}

}  // namespace
}  // namespace luxel::voxel

namespace luxel::voxel {
namespace {

TEST(SunVisibility, MemoryEstimateCountsWhatEachMethodBuilds) {
    ShadowSettings s;
    const Int3 world{64, 32, 64};
    s.method = ShadowMethod::Hard;
    EXPECT_EQ(estimateSunVisibilityBytes(world, s), 0u);
    s.method = ShadowMethod::Sdf;
    const std::uint64_t sdf = estimateSunVisibilityBytes(world, s);
    EXPECT_GE(sdf, 64u * 32 * 64 * 8);  // at least the stored distances and features
    s.method = ShadowMethod::Msm;
    s.mapSize = 512;
    const std::uint64_t msm = estimateSunVisibilityBytes(world, s);
    EXPECT_GE(msm, 512u * 512 * 16);  // at least one fp32 moment vector per texel
    s.msmFilter = ShadowSettings::MsmFilter::PenumbraSized;
    EXPECT_GE(estimateSunVisibilityBytes(world, s), msm + 513u * 513 * 32);
    s.method = ShadowMethod::Blend;
    EXPECT_GE(estimateSunVisibilityBytes(world, s), sdf + msm);
    // The largest world's distance transform is far beyond any machine: build() refuses it
    // before allocating (checkMemory), instead of failing inside the transform.
    s.method = ShadowMethod::Sdf;
    EXPECT_GT(estimateSunVisibilityBytes({kMaxWorldSide, kMaxWorldSide, kMaxWorldSide}, s),
              std::uint64_t{1} << 40);
}

}  // namespace
}  // namespace luxel::voxel
