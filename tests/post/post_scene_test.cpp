// The "post" section of voxel scene files: values reach PostOptions, mistakes name the field.
#include <gtest/gtest.h>

#include <string>

#include "luxel/voxel/voxel_scene.h"
#include "support/temp_dir.h"

namespace luxel::post {
namespace {

std::string sceneWithPost(const test::TempDir& tmp, const std::string& name,
                          const std::string& post) {
    return tmp.write(name, R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
        "camera": {"position": [4, 4, -8], "look_at": [4, 4, 4], "size": [16, 8]},
        "post": )" + post + "}");
}

TEST(PostScene, ReadsEveryField) {
    const test::TempDir tmp;
    auto scene = voxel::loadVoxelScene(sceneWithPost(tmp, "ok.json", R"({
        "bloom": {"strength": 0.2, "levels": 4, "karis": true}, "exposure": -1.5,
        "tone": "reinhard", "internal_scale": 0.5, "upscaler": "bilinear", "sharpness": 0.3})"));
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const PostOptions& p = scene->post;
    EXPECT_FLOAT_EQ(p.bloom.strength, 0.2f);
    EXPECT_EQ(p.bloom.levels, 4);
    EXPECT_TRUE(p.bloom.karisAverage);
    EXPECT_FLOAT_EQ(p.tone.exposureStops, -1.5f);
    EXPECT_EQ(p.tone.curve, ToneCurve::Reinhard);
    EXPECT_FLOAT_EQ(p.internalScale, 0.5f);
    EXPECT_EQ(p.upscaler, Upscaler::Bilinear);
    EXPECT_FLOAT_EQ(p.sharpness, 0.3f);
}

TEST(PostScene, DefaultsWithoutTheSection) {
    const auto path = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/garden.json";
    auto scene = voxel::loadVoxelScene(path, 16, 8);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->post.bloom.strength, 0.0f);
    EXPECT_EQ(scene->post.internalScale, 1.0f);
}

TEST(PostScene, MistakesNameTheField) {
    const test::TempDir tmp;
    const std::pair<const char*, const char*> cases[] = {
        {R"({"blooom": {}})", "unknown field 'blooom'"},
        {R"({"bloom": {"strength": 2}})", "post.bloom.strength: must be in 0..1"},
        {R"({"bloom": {"levels": 2.5}})", "post.bloom.levels: must be a whole number"},
        {R"({"bloom": {"radius": 1}})", "unknown field 'radius'"},
        {R"({"tone": "filmic"})", "post.tone: unknown tone curve 'filmic'"},
        {R"({"internal_scale": 0.1})", "post.internal_scale: must be in 0.25..1"},
        {R"({"upscaler": "fsr"})", "post.upscaler: unknown upscaler 'fsr'"},
        {R"({"exposure": "bright"})", "post.exposure"},
        {R"([1, 2])", "post"},
    };
    int i = 0;
    for (auto [post, expected] : cases) {
        const std::string path = sceneWithPost(tmp, "bad" + std::to_string(i++) + ".json", post);
        auto scene = voxel::loadVoxelScene(path);
        ASSERT_FALSE(scene.ok()) << post;
        EXPECT_NE(scene.error().message().find(expected), std::string::npos)
            << scene.error().message();
    }
}

}  // namespace
}  // namespace luxel::post
