// Voxel scene files: the shipped default scene loads; bad input gives located errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "luxel/voxel/voxel_scene.h"
#include "support/temp_dir.h"

namespace luxel::voxel {
namespace {

TEST(VoxelScene, ShippedDefaultSceneLoads) {
    const std::string path = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json";
    auto scene = loadVoxelScene(path, 64, 36);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->world.size(), (Int3{256, 96, 256}));
    EXPECT_GT(scene->world.solidCount(), 1000000u);
    EXPECT_EQ(scene->camera.width(), 64);
    EXPECT_EQ(scene->shading.maxReflections, 4);
    EXPECT_EQ(scene->shading.reflectionMode, ShadeOptions::ReflectionMode::EnergyConserving);
    EXPECT_EQ(scene->shading.lighting, ShadeOptions::Lighting::Physical);
}

TEST(VoxelScene, VoxFileWorldsAndShapes) {
    const test::TempDir tmp;
    const std::string path = tmp.write("vox.json", R"({"type": "voxel",
        "world": {"source": "vox", "file": ")" + std::string(LUXEL_SOURCE_DIR) +
                                                       R"(/scenes/voxel/sample.vox",
                  "shapes": [{"type": "box", "min": [0, 0, 0], "max": [2, 2, 2]}]},
        "camera": {"position": [10, 10, -20], "look_at": [10, 5, 10]}})");
    auto scene = loadVoxelScene(path);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_TRUE(scene->world.solid(1, 1, 1));
}

TEST(VoxelScene, BadInputIsLocated) {
    const test::TempDir tmp;
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
        const std::string path = tmp.write("bad" + std::to_string(i++) + ".json", c.text);
        auto scene = loadVoxelScene(path);
        ASSERT_FALSE(scene.ok()) << c.text;
        EXPECT_NE(scene.error().message().find(c.expected), std::string::npos)
            << scene.error().message();
        EXPECT_NE(scene.error().message().find(path), std::string::npos);
    }
}

}  // namespace
}  // namespace luxel::voxel

namespace luxel::voxel {
namespace {

// A scene in `tmp` next to a copy of the shipped textures, so relative paths resolve.
std::string textureScene(const test::TempDir& tmp, const std::string& name,
                         const std::string& body) {
    std::filesystem::create_directories(tmp.dir() / "textures");
    for (const char* t : {"bricks.png", "leaves.png"}) {
        std::filesystem::copy_file(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/textures/" + t,
                                   tmp.dir() / "textures" / t,
                                   std::filesystem::copy_options::overwrite_existing);
    }
    return tmp.write(name, body);
}

const char* kTextures = R"("textures": [{"name": "bricks", "file": "textures/bricks.png"},
                           {"name": "leaves", "file": "textures/leaves.png", "reflectivity": 0.5}],)";

TEST(VoxelScene, TexturesOnShapesAndByColour) {
    const test::TempDir tmp;
    const std::string path =
        textureScene(tmp, "ok.json", std::string(R"({"type": "voxel", )") + kTextures + R"(
        "world": {"source": "random", "size": [16, 8, 16], "density": 0.3,
                  "color": [80, 150, 60],
                  "shapes": [{"type": "box", "min": [2, 1, 2], "max": [4, 3, 4],
                              "texture": "bricks"}],
                  "texture_by_color": [{"color": [84, 146, 60], "tolerance": 4,
                                        "texture": "leaves"}]},
        "camera": {"position": [8, 6, -8], "look_at": [8, 0, 8]}})");
    auto scene = loadVoxelScene(path);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    ASSERT_EQ(scene->textures.size(), 2);
    EXPECT_EQ(scene->textures[0].width, 16);
    EXPECT_EQ(scene->textures[1].reflectivity, 0.5f);
    EXPECT_EQ(scene->world.get(3, 2, 3), (Voxel{255, 255, 255, alphaForSlot(0)}));
    // Every random voxel matched the colour rule (within 4 per channel) and became leaves.
    int leaves = 0, plain = 0;
    for (int z = 0; z < 16; ++z) {
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 16; ++x) {
                const Voxel v = scene->world.get(x, y, z);
                leaves += v.a == alphaForSlot(1);
                plain += v.a == kPlainBlockAlpha;
            }
        }
    }
    EXPECT_GT(leaves, 100);
    EXPECT_EQ(plain, 0);
}

TEST(VoxelScene, TextureErrorsAreLocated) {
    const test::TempDir tmp;
    struct Case {
        std::string textures, shapes, expected;
    };
    const std::string box = R"({"type": "box", "min": [0, 0, 0], "max": [2, 2, 2])";
    std::string many = R"("textures": [)";
    for (int i = 0; i < 255; ++i) {
        many += std::string(i ? ", " : "") + R"({"name": "t)" + std::to_string(i) +
                R"(", "file": "textures/bricks.png"})";
    }
    many += "],";
    const Case cases[] = {
        {kTextures, box + R"(, "texture": "leafs"})",
         "world.shapes[0].texture: unknown texture 'leafs' (defined: bricks, leaves)"},
        {R"("textures": [{"name": "x", "file": "textures/missing.png"}],)", box + "}",
         "textures[0].file:"},
        {R"("textures": [{"name": "x", "file": "bad2.json"}],)", box + "}",  // not a PNG
         "textures[0].file:"},
        {R"("textures": [{"name": "x", "file": "textures/bricks.png"},
                         {"name": "x", "file": "textures/leaves.png"}],)",
         box + "}", "textures[1].name: texture 'x' is defined twice"},
        {R"("textures": [{"name": "x", "file": "textures/bricks.png", "reflectivity": 2}],)",
         box + "}", "textures[0].reflectivity: must be in 0..1"},
        {R"("textures": [{"name": "x", "file": "textures/bricks.png", "size": 2}],)", box + "}",
         "unknown field 'size'"},
        {many, box + "}", "textures: has 255 entries, at most 254"},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string name = "bad" + std::to_string(i++) + ".json";
        const std::string path = textureScene(tmp, name,
                                              R"({"type": "voxel", )" + c.textures + R"(
            "world": {"source": "empty", "size": [8, 8, 8], "shapes": [)" +
                                                  c.shapes + R"(]},
            "camera": {"position": [0, 0, 0]}})");
        auto scene = loadVoxelScene(path);
        ASSERT_FALSE(scene.ok()) << c.expected;
        EXPECT_NE(scene.error().message().find(c.expected), std::string::npos)
            << scene.error().message();
        EXPECT_NE(scene.error().message().find(path + ":"), std::string::npos)
            << scene.error().message();
    }
}

// parseVoxelScene reads from text (the fuzz target uses it): the same scene as loading the file,
// files resolved next to the given path, errors located in that path.
TEST(VoxelScene, ParsesFromTextLikeTheFile) {
    const std::string path = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/garden.json";
    std::ifstream in(path);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    auto fromFile = loadVoxelScene(path);
    auto fromText = parseVoxelScene(text, path);
    ASSERT_TRUE(fromFile.ok()) << fromFile.error().message();
    ASSERT_TRUE(fromText.ok()) << fromText.error().message();
    EXPECT_EQ(fromText->world.size(), fromFile->world.size());
    EXPECT_EQ(fromText->world.solidCount(), fromFile->world.solidCount());
    EXPECT_EQ(fromText->textures.size(), fromFile->textures.size());
    EXPECT_GT(fromText->textures.size(), 0);

    auto bad = parseVoxelScene(R"({"type": "voxel", "world": {"source": "empty"}})", "t/x.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message().rfind("t/x.json:1:", 0), 0u) << bad.error().message();
}

}  // namespace
}  // namespace luxel::voxel
