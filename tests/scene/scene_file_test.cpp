// The one scene-file reader: one read and parse, the type picks the reader, errors located.
#include "luxel/scene/scene_file.h"

#include <gtest/gtest.h>

#include <string>

#include "support/temp_dir.h"

namespace luxel::scene {
namespace {

TEST(SceneFile, TheTypePicksTheReader) {
    const test::TempDir tmp;
    auto twoD = loadSceneFile(std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/room.json");
    ASSERT_TRUE(twoD.ok()) << twoD.error().message();
    EXPECT_EQ(twoD->kind(), SceneKind::TwoD);
    EXPECT_GT(twoD->twoD().shapes.size(), 0u);
    auto voxel =
        loadSceneFile(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json", {{64, 36}});
    ASSERT_TRUE(voxel.ok()) << voxel.error().message();
    EXPECT_EQ(voxel->kind(), SceneKind::Voxel);
    EXPECT_EQ(voxel->voxel().camera.width(), 64);  // the size override reaches the camera
    EXPECT_EQ(voxel->voxel().camera.height(), 36);
    auto explicit2D = loadSceneFile(tmp.write("typed.json", R"({"type": "2d", "canvas": [8, 8]})"));
    ASSERT_TRUE(explicit2D.ok()) << explicit2D.error().message();
    EXPECT_EQ(explicit2D->kind(), SceneKind::TwoD);
}

TEST(SceneFile, BadFilesGiveLocatedErrors) {
    const test::TempDir tmp;
    auto missing = loadSceneFile("/nonexistent/x.json");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message().find("cannot open scene '/nonexistent/x.json'"),
              std::string::npos);
    const std::string malformed = tmp.write("bad.json", "{\"canvas\": [8,\n 8,]}");
    auto bad = loadSceneFile(malformed);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message().rfind(malformed + ":2:", 0), 0u) << bad.error().message();
    const std::string unknown = tmp.write("unknown.json", R"({"type": "mesh"})");
    auto wrongType = loadSceneFile(unknown);
    ASSERT_FALSE(wrongType.ok());
    EXPECT_EQ(wrongType.error().message(),
              unknown + ":1:10: type: unknown scene type 'mesh' (known: 2d, voxel, octree)");
    const std::string noTree = tmp.write("notree.json", R"({"type": "octree"})");
    auto treeless = loadSceneFile(noTree);
    ASSERT_FALSE(treeless.ok());
    EXPECT_EQ(treeless.error().message(), noTree + ":1:1: an octree scene needs \"octree\"");
}

}  // namespace
}  // namespace luxel::scene
