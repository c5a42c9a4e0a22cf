// MagicaVoxel export: world -> .vox -> world is the same world, including worlds over 256 a side
// (split into models placed by a scene graph) and materials (MATL).
#include <gtest/gtest.h>

#include <filesystem>

#include "luxel/voxel/generators.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/vox_import.h"
#include "luxel/voxel/vox_scene.h"
#include "support/temp_dir.h"

namespace luxel::voxel {
namespace {

TEST(VoxExport, WorldsOver256ASideSplitIntoPlacedModels) {
    VoxelWorld w = VoxelWorld::create({300, 20, 530}, 16).value();
    addBox(w, {0, 0, 0}, {300, 1, 530}, Voxel{10, 200, 10, 255});
    addSphere(w, {150, 10, 260}, 9, Voxel{200, 10, 10, 255});
    w.set(299, 19, 529, Voxel{1, 2, 3, 255});
    w.set(0, 19, 0, Voxel{4, 5, 6, 255});
    Result<VoxExport> e = exportVox(w);
    ASSERT_TRUE(e.ok()) << e.error().message();
    EXPECT_EQ(e->models, 2 * 3);  // vox x 300 -> 2 tiles, vox y (luxel z) 530 -> 3, z 20 -> 1
    EXPECT_TRUE(e->warnings.empty());
    EXPECT_EQ(e->bytes[4], 200);  // version 200
    Result<VoxImport> back = readVox(e->bytes, "big.vox", {16});
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_TRUE(back->warnings.empty());
    EXPECT_TRUE(w == back->world);
}

TEST(VoxExport, EmptyCornerTilesKeepTheWorldSize) {
    // Voxels only in the middle of a 600-wide world: the corner tiles are written anyway.
    VoxelWorld w = VoxelWorld::create({600, 8, 8}, 8).value();
    w.set(300, 4, 4, Voxel{9, 9, 9, 255});
    Result<VoxExport> e = exportVox(w);
    ASSERT_TRUE(e.ok()) << e.error().message();
    EXPECT_EQ(e->models, 3);
    Result<VoxImport> back = readVox(e->bytes, "mid.vox", {8});
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_TRUE(w == back->world);
}

TEST(VoxExport, MaterialsRoundTrip) {
    MaterialTable table;
    Material metal = defaultMaterial();
    metal.name = "metal";
    metal.metallic = 1.0f;
    metal.roughness = 0.25f;
    Material glass = defaultMaterial();
    glass.name = "glass";
    glass.transmission = 0.8f;
    glass.ior = 1.4f;
    glass.roughness = 0.05f;
    Material lamp = defaultMaterial();
    lamp.name = "lamp";
    lamp.emission = {12.0f, 12.0f, 12.0f};
    ASSERT_TRUE(table.setSlot(0, metal).ok());
    ASSERT_TRUE(table.setSlot(1, glass).ok());
    ASSERT_TRUE(table.setSlot(2, lamp).ok());
    VoxelWorld w = VoxelWorld::create({4, 2, 3}, 4).value();
    w.set(0, 0, 0, Voxel{180, 180, 190, alphaForSlot(0)});
    w.set(1, 0, 0, Voxel{255, 255, 255, alphaForSlot(1)});
    w.set(2, 0, 0, Voxel{255, 255, 255, alphaForSlot(2)});
    w.set(3, 1, 2, Voxel{40, 50, 60, kPlainBlockAlpha});
    Result<VoxExport> e = exportVox(w, &table);
    ASSERT_TRUE(e.ok()) << e.error().message();
    Result<VoxImport> back = readVox(e->bytes, "mat.vox", {4});
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_TRUE(back->warnings.empty()) << back->warnings.front();
    EXPECT_EQ(back->world.size(), w.size());
    EXPECT_EQ(back->world.solidCount(), w.solidCount());
    const auto materialOf = [&](int x, int y, int z) -> Material {
        const int slot = textureSlotOf(back->world.get(x, y, z));
        return slot < 0 ? defaultMaterial() : back->materials.at(static_cast<std::size_t>(slot));
    };
    const Material m0 = materialOf(0, 0, 0), m1 = materialOf(1, 0, 0), m2 = materialOf(2, 0, 0);
    EXPECT_NEAR(m0.metallic, 1.0f, 1e-5);
    EXPECT_NEAR(m0.roughness, 0.25f, 1e-5);
    EXPECT_NEAR(m1.transmission, 0.8f, 1e-5);
    EXPECT_NEAR(m1.ior, 1.4f, 1e-5);
    EXPECT_NEAR(m1.roughness, 0.05f, 1e-5);
    EXPECT_NEAR(m2.emission.r, 12.0f, 1e-3);
    EXPECT_NEAR(m2.emission.b, 12.0f, 1e-3);
    // Colours come back exactly; the plain block stays plain.
    for (int x = 0; x < 3; ++x) {
        const Voxel a = w.get(x, 0, 0), b = back->world.get(x, 0, 0);
        EXPECT_EQ((Voxel{a.r, a.g, a.b, 0}), (Voxel{b.r, b.g, b.b, 0})) << x;
    }
    EXPECT_EQ(back->world.get(3, 1, 2), (Voxel{40, 50, 60, kPlainBlockAlpha}));

    // Through a scene: materials land in the scene's table, and export again gives the same.
    Result<VoxelScene> scene = voxSceneFromBytes(e->bytes, "mat.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    Result<VoxExport> again = exportVox(scene->world, &scene->shading.materials);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->bytes, e->bytes);
}

TEST(VoxExport, TexturedVoxelsAreWrittenAsTheirColourWithAWarning) {
    VoxelWorld w = VoxelWorld::create({2, 2, 2}, 4).value();
    w.set(0, 0, 0, Voxel{10, 20, 30, alphaForSlot(4)});
    Result<VoxExport> e = exportVox(w);
    ASSERT_TRUE(e.ok());
    ASSERT_EQ(e->warnings.size(), 1u);
    EXPECT_NE(e->warnings[0].find("textured voxels are written as their colour"),
              std::string::npos);
    Result<VoxImport> back = readVox(e->bytes, "t.vox", {4});
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->world.get(0, 0, 0), (Voxel{10, 20, 30, 255}));
}

TEST(VoxExport, WriteReplacesTheFileOnlyWhenComplete) {
    const test::TempDir tmp;
    const std::filesystem::path& dir = tmp.dir();
    VoxelWorld w = VoxelWorld::create({3, 3, 3}, 4).value();
    w.set(1, 1, 1, Voxel{7, 8, 9, 255});
    const std::string path = tmp.path("w.vox");
    Result<std::vector<std::string>> written = writeVox(w, path);
    ASSERT_TRUE(written.ok()) << written.error().message();
    Result<VoxelWorld> loaded = loadVox(path, 4);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    EXPECT_TRUE(w == *loaded);
    // Only the target remains in the folder (the temporary file was renamed over it).
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        files += entry.is_regular_file();
    EXPECT_EQ(files, 1);
}

}  // namespace
}  // namespace luxel::voxel
