// The scene file's shadow fields: every key read, booleans still accepted, bad values named.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "luxel/voxel/voxel_scene.h"
#include "support/temp_dir.h"

namespace luxel::voxel {
namespace {

Result<VoxelScene> loadWithRender(const test::TempDir& tmp, const std::string& name,
                                  const std::string& render) {
    return loadVoxelScene(
        tmp.write(name, R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
        "camera": {"position": [4, 6, -4], "look_at": [4, 2, 4], "fov": 60, "size": [8, 8]},
        "render": )" + render +
                            "}"));
}

TEST(ShadowJson, ReadsEveryField) {
    const test::TempDir tmp;
    auto scene = loadWithRender(tmp, "all.json", R"({"shadows": {"method": "blend", "samples": 64,
        "map_size": 256, "storage": "16bit", "filter": "box", "filter_radius": 3,
        "moment_bias": 0.0001, "light_bleed": 0.2, "depth_bias": 0.1, "normal_offset": 0.3,
        "sdf_normal_offset": 0.07,
        "sdf_steps": 32, "sdf_distance": "centres", "blend_near": 10, "blend_far": 20, "split": "msm-near",
        "combine": "min", "msm_filter": "penumbra"}, "sun_radius": 2})");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const ShadowSettings& s = scene->shading.shadowSettings;
    EXPECT_TRUE(scene->shading.shadows);
    EXPECT_EQ(s.method, ShadowMethod::Blend);
    EXPECT_EQ(s.exactSamples, 64);
    EXPECT_EQ(s.mapSize, 256);
    EXPECT_EQ(s.momentStorage, ShadowSettings::MomentStorage::Quantized16);
    EXPECT_EQ(s.momentFilter, ShadowSettings::MomentFilter::Box);
    EXPECT_EQ(s.filterRadius, 3.0);
    EXPECT_EQ(s.momentBias, 0.0001);
    EXPECT_EQ(s.lightBleedReduction, 0.2);
    EXPECT_EQ(s.depthBias, 0.1);
    EXPECT_EQ(s.normalOffset, 0.3);
    EXPECT_EQ(s.sdfNormalOffset, 0.07);
    EXPECT_EQ(s.sdfMaxSteps, 32);
    EXPECT_EQ(s.sdfDistance, ShadowSettings::SdfDistance::Centres);
    EXPECT_EQ(s.blendNear, 10.0);
    EXPECT_EQ(s.blendFar, 20.0);
    EXPECT_FALSE(s.sdfNear);
    EXPECT_TRUE(s.minInBand);
    EXPECT_EQ(s.msmFilter, ShadowSettings::MsmFilter::PenumbraSized);
    EXPECT_NEAR(scene->shading.sunAngularRadius, 2.0 * std::numbers::pi / 180.0, 1e-12);
}

TEST(ShadowJson, BooleansStillWork) {
    const test::TempDir tmp;
    auto off = loadWithRender(tmp, "off.json", R"({"shadows": false})");
    ASSERT_TRUE(off.ok()) << off.error().message();
    EXPECT_FALSE(off->shading.shadows);
    auto on = loadWithRender(tmp, "on.json", R"({"shadows": true})");
    ASSERT_TRUE(on.ok()) << on.error().message();
    EXPECT_TRUE(on->shading.shadows);
    EXPECT_EQ(on->shading.shadowSettings.method, ShadowMethod::Hard);
}

TEST(ShadowJson, BadValuesNameTheField) {
    const test::TempDir tmp;
    const std::pair<const char*, const char*> cases[] = {
        {R"({"shadows": 3})", "render.shadows: must be true, false or an object"},
        {R"({"shadows": {"method": "pcss"}})", "render.shadows.method: must be one of"},
        {R"({"shadows": {"samples": 0}})", "render.shadows.samples"},
        {R"({"shadows": {"map_size": 1.5}})", "render.shadows.map_size"},
        {R"({"shadows": {"storage": "8bit"}})", "render.shadows.storage"},
        {R"({"shadows": {"filter_radius": -1}})", "render.shadows.filter_radius"},
        {R"({"shadows": {"blend_near": 30, "blend_far": 20}})", "render.shadows.blend_far"},
        {R"({"shadows": {"split": "left"}})", "render.shadows.split"},
        {R"({"shadows": {"combine": "max"}})", "render.shadows.combine"},
        {R"({"shadows": {"sdf_distance": "edges"}})", "render.shadows.sdf_distance"},
        {R"({"shadows": {"msm_filter": "pcss"}})", "render.shadows.msm_filter"},
        {R"({"shadows": {"softness": 1}})", "unknown field 'softness'"},
        {R"({"sun_radius": 45})", "render.sun_radius"},
    };
    int i = 0;
    for (const auto& [render, needle] : cases) {
        auto scene = loadWithRender(tmp, "bad" + std::to_string(i++) + ".json", render);
        ASSERT_FALSE(scene.ok()) << render;
        EXPECT_NE(scene.error().message().find(needle), std::string::npos)
            << scene.error().message();
    }
}

}  // namespace
}  // namespace luxel::voxel
