// luxel-view on MagicaVoxel files: a .vox opens directly (framed by its own camera), a click
// removes a voxel, and Ctrl+S saves the edited world as a .vox the loader reads back. The saver
// alone, without a display, mirrors the renderer's edits.
#include <gtest/gtest.h>

#include <filesystem>

#include "luxel/voxel/vox_import.h"
#include "luxel/voxel/vox_scene.h"
#include "support/temp_dir.h"
#include "viewer_xvfb.h"
#include "voxel_controls.h"

namespace {

namespace fs = std::filesystem;
using luxel::test::RunResult;
using luxel::test::ViewerXvfb;

const std::string kSample = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/sample.vox";

TEST(VoxelSaver, MirrorsEditsAndWritesAVoxTheLoaderReads) {
    auto scene = luxel::voxel::loadVoxScene(kSample, {64, 36});
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const luxel::test::TempDir tmp;
    const fs::path out = tmp.dir() / "saver.vox";
    luxel::viewer::VoxelSaver saver(scene->world, scene->shading.materials, out.string());
    luxel::viewer::VoxelEdit edit;
    edit.ray = scene->camera.primaryRay(32, 18);
    edit.add = false;
    luxel::voxel::VoxelWorld expected = scene->world;
    ASSERT_TRUE(luxel::viewer::applyVoxelEdit(expected, edit));
    saver.edit(edit);
    ASSERT_TRUE(saver.save()) << saver.status();
    EXPECT_EQ(saver.status().rfind("saved ", 0), 0u) << saver.status();
    auto loaded = luxel::voxel::loadVox(out.string());
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    EXPECT_TRUE(*loaded == expected);
    EXPECT_EQ(loaded->solidCount() + 1, scene->world.solidCount());

    luxel::viewer::VoxelSaver bad(scene->world, {}, "/nonexistent-dir/x.vox");
    EXPECT_FALSE(bad.save());
    EXPECT_NE(bad.status().find("save failed: "), std::string::npos) << bad.status();
    EXPECT_EQ(luxel::viewer::defaultVoxSavePath("/a/b/m.vox"), "/a/b/m.edited.vox");
}

TEST_F(ViewerXvfb, OpensAVoxAndSavesTheEditedWorld) {
    fs::copy_file(kSample, path("m.vox"));
    write("save.txt",
          "wait_render\n"
          "click 160 90\n"
          "wait_render\n"
          "key ctrl+s\n"
          "quit\n");
    const RunResult r = view(
        "m.vox --size 320x180 --internal-size 320x180 --backend cpu "
        "--script save.txt");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("luxel-view: saved "), std::string::npos) << r.output;
    auto original = luxel::voxel::loadVox(path("m.vox"));
    auto saved = luxel::voxel::loadVox(path("m.edited.vox"));
    ASSERT_TRUE(original.ok() && saved.ok()) << r.output;
    EXPECT_EQ(saved->size(), original->size());
    EXPECT_EQ(saved->solidCount() + 1, original->solidCount());  // the click removed one
}

}  // namespace
