// Voxel scene files: the shipped default scene loads; bad input gives located errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "luxel/voxel/voxel_scene.h"

namespace luxel::voxel {
namespace {

std::string writeScene(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("luxel_voxel_scene_" + name);
    std::ofstream(path) << text;
    return path.string();
}

TEST(VoxelScene, ShippedDefaultSceneLoads) {
    const std::string path = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json";
    ASSERT_TRUE(isVoxelSceneFile(path));
    auto scene = loadVoxelScene(path, 64, 36);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->world.size(), (Int3{256, 96, 256}));
    EXPECT_GT(scene->world.solidCount(), 1000000u);
    EXPECT_EQ(scene->camera.width(), 64);
    EXPECT_EQ(scene->shading.maxReflections, 2);
    EXPECT_EQ(scene->shading.reflectionMode, ShadeOptions::ReflectionMode::EnergyConserving);
    EXPECT_FALSE(isVoxelSceneFile(std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/room.json"));
}

TEST(VoxelScene, VoxFileWorldsAndShapes) {
    const std::string path = writeScene("vox.json", R"({"type": "voxel",
        "world": {"source": "vox", "file": ")" + std::string(LUXEL_SOURCE_DIR) +
                                                        R"(/scenes/voxel/sample.vox",
                  "shapes": [{"type": "box", "min": [0, 0, 0], "max": [2, 2, 2]}]},
        "camera": {"position": [10, 10, -20], "look_at": [10, 5, 10]}})");
    auto scene = loadVoxelScene(path);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_TRUE(scene->world.solid(1, 1, 1));
}

TEST(VoxelScene, BadInputIsLocated) {
    struct Case {
        const char* text;
        const char* expected;
    };
    const Case cases[] = {
        {R"({"type": "voxel", "world": {"source": "terrain", "size": [0, 8, 8]},
             "camera": {"position": [0, 0, 0]}})",
         "world.size[0]: must be in 1..4096"},
        {R"({"type": "voxel", "world": {"source": "lava", "size": [8, 8, 8]},
             "camera": {"position": [0, 0, 0]}})",
         "unknown world source 'lava'"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8], "sizee": 1},
             "camera": {"position": [0, 0, 0]}})",
         "unknown field 'sizee'"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
             "camera": {"position": [0, 0, 0], "fov": 200}})",
         "camera.fov: must be in 1..179"},
        {R"({"type": "voxel", "world": {"source": "vox", "file": "missing.vox"},
             "camera": {"position": [0, 0, 0]}})",
         "missing.vox"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
             "camera": {"position": [0, 0, 0]}, "sun": [0, 0, 0]})",
         "sun: must not be zero"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
             "camera": {"position": [0, 0, 0]}, "render": {"reflections": NaN}})",
         "invalid JSON"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [4000, 4000, 4000]},
             "camera": {"position": [0, 0, 0]}})",
         "only"},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string path = writeScene("bad" + std::to_string(i++) + ".json", c.text);
        auto scene = loadVoxelScene(path);
        ASSERT_FALSE(scene.ok()) << c.text;
        EXPECT_NE(scene.error().message().find(c.expected), std::string::npos)
            << scene.error().message();
        EXPECT_NE(scene.error().message().find(path), std::string::npos);
    }
}

}  // namespace
}  // namespace luxel::voxel
