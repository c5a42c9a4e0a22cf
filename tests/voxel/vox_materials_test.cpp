// MagicaVoxel materials (MATL) and palette alpha mapped to luxel materials, the warnings for what
// luxel cannot show or does not use, and a .vox opened as a scene.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/core/tonemap.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/vox_import.h"
#include "luxel/voxel/vox_scene.h"
#include "support/temp_dir.h"
#include "support/vox_writer.h"

namespace luxel::voxel {
namespace {

namespace vw = luxel::test::vox;

// One voxel per colour index 1..n in a row along x.
vw::Bytes row(int n, const vw::Bytes& extra) {
    std::vector<vw::Voxel4> voxels;
    for (int i = 1; i <= n; ++i)
        voxels.push_back({static_cast<std::uint8_t>(i - 1), 0, 0, static_cast<std::uint8_t>(i)});
    return vw::file(vw::cat({vw::model(n, 1, 1, voxels), extra}));
}

const Material& materialAt(const VoxImport& r, int x) {
    const int slot = textureSlotOf(r.world.get(x, 0, 0));
    EXPECT_GE(slot, 0) << "voxel " << x << " has no material";
    return r.materials.at(static_cast<std::size_t>(std::max(slot, 0)));
}

bool hasWarning(const VoxImport& r, const std::string& text) {
    for (const std::string& w : r.warnings) {
        if (w.find(text) != std::string::npos) return true;
    }
    return false;
}

TEST(VoxMaterials, EachTypeMapped) {
    const vw::Bytes bytes = row(
        7,
        vw::cat(
            {vw::palette({{5, {255, 128, 0, 255}}}), vw::material(1, {{"_type", "_diffuse"}}),
             vw::material(
                 2, {{"_type", "_metal"}, {"_metal", "0.8"}, {"_rough", "0.2"}, {"_spec", "0.5"}}),
             vw::material(
                 3, {{"_type", "_glass"}, {"_trans", "0.9"}, {"_rough", "0.05"}, {"_ior", "0.33"}}),
             vw::material(4, {{"_type", "_glass"}, {"_alpha", "0.5"}, {"_ri", "2.0"}}),
             vw::material(5, {{"_type", "_emit"}, {"_emit", "0.5"}, {"_flux", "2"}}),
             vw::material(6, {{"_type", "_blend"}, {"_metal", "0.5"}, {"_trans", "0.3"}}),
             vw::material(7, {{"_type", "_media"}, {"_media_type", "_cld"}})}));
    Result<VoxImport> r = readVox(bytes, "m.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->world.get(0, 0, 0).a, kPlainBlockAlpha);  // diffuse: a plain block
    const Material& metal = materialAt(*r, 1);
    EXPECT_FLOAT_EQ(metal.metallic, 0.8f);
    EXPECT_FLOAT_EQ(metal.roughness, 0.2f);
    EXPECT_EQ(metal.transmission, 0.0f);
    const Material& glass = materialAt(*r, 2);
    EXPECT_FLOAT_EQ(glass.transmission, 0.9f);
    EXPECT_FLOAT_EQ(glass.roughness, 0.05f);
    EXPECT_NEAR(glass.ior, 1.33f, 1e-6);  // _ior is the index minus one
    EXPECT_EQ(glass.absorption.r, 0.0f);  // white glass absorbs nothing
    const Material& glass2 = materialAt(*r, 3);
    EXPECT_FLOAT_EQ(glass2.transmission, 0.5f);
    EXPECT_FLOAT_EQ(glass2.ior, 2.0f);
    const Material& emit = materialAt(*r, 4);
    // linear colour x 4 x _emit x 2^_flux: orange (255, 128, 0) -> (8, 8 * lin(128/255), 0)
    EXPECT_NEAR(emit.emission.r, 8.0f, 1e-4);
    EXPECT_NEAR(emit.emission.g, 8.0f * srgbToLinear(128 / 255.0f), 1e-4);
    EXPECT_EQ(emit.emission.b, 0.0f);
    const Material& blend = materialAt(*r, 5);
    EXPECT_FLOAT_EQ(blend.metallic, 0.5f);
    EXPECT_FLOAT_EQ(blend.transmission, 0.3f);
    EXPECT_EQ(r->world.get(6, 0, 0).a, kPlainBlockAlpha);  // media: diffuse
    EXPECT_EQ(r->materials.size(), 5u);
    for (const Material& m : r->materials) EXPECT_TRUE(validateMaterial(m).ok()) << m.name;
    EXPECT_TRUE(hasWarning(*r, "m.vox: MATL 7: _media _cld approximated as diffuse"));
    EXPECT_TRUE(hasWarning(*r, "m.vox: MATL 6: _blend approximated as one surface"));
    EXPECT_TRUE(hasWarning(*r, "m.vox: MATL 2: _spec (specular) has no luxel equivalent"));
    EXPECT_EQ(r->warnings.size(), 3u);
}

TEST(VoxMaterials, SameMaterialsShareASlotAndWarningsGroupIds) {
    vw::Bytes matl;
    for (int i = 1; i <= 4; ++i) {
        matl = vw::cat(
            {matl, vw::material(i, {{"_type", "_metal"}, {"_metal", "1"}, {"_plastic", "1"}})});
    }
    Result<VoxImport> r = readVox(row(4, matl), "s.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->materials.size(), 1u);
    EXPECT_EQ(r->materials[0].name, "vox 1");
    ASSERT_EQ(r->warnings.size(), 1u);
    EXPECT_EQ(r->warnings[0],
              "s.vox: MATL 1, 2, 3 and 4: _plastic (plastic) has no luxel equivalent; ignored");
}

TEST(VoxMaterials, PaletteAlphaIsOpacity) {
    const vw::Bytes bytes = row(
        3, vw::palette({{1, {200, 200, 200, 128}}, {2, {10, 20, 30, 0}}, {3, {90, 90, 90, 255}}}));
    Result<VoxImport> r = readVox(bytes, "a.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    const Material& half = materialAt(*r, 0);
    EXPECT_NEAR(half.transmission, 1.0f - 128 / 255.0f, 1e-6);
    EXPECT_EQ(half.ior, 1.0f);  // see-through, unbent
    EXPECT_EQ(r->world.get(0, 0, 0).r, 200);
    EXPECT_FALSE(r->world.solid(1, 0, 0));  // alpha 0: left out
    EXPECT_EQ(r->world.get(2, 0, 0), (Voxel{90, 90, 90, 255}));
    EXPECT_TRUE(hasWarning(*r, "a.vox: palette index 2: alpha 0: its voxels are left out"));

    // A palette written without alpha (0 for every colour used) reads as opaque.
    const vw::Bytes noAlpha = row(2, vw::palette({{1, {1, 2, 3, 0}}, {2, {4, 5, 6, 0}}}));
    Result<VoxImport> opaque = readVox(noAlpha, "n.vox", {4});
    ASSERT_TRUE(opaque.ok()) << opaque.error().message();
    EXPECT_EQ(opaque->world.get(0, 0, 0), (Voxel{1, 2, 3, 255}));
    EXPECT_EQ(opaque->world.get(1, 0, 0), (Voxel{4, 5, 6, 255}));
    ASSERT_EQ(opaque->warnings.size(), 1u);
    EXPECT_EQ(opaque->warnings[0],
              "n.vox: palette: alpha is 0 for every colour used; read as opaque");
}

TEST(VoxMaterials, UnusedChunksAreWarnedOncePerKind) {
    const vw::Bytes bytes =
        row(1, vw::cat({vw::chunk("rOBJ", vw::dict({{"_type", "_bg"}})),
                        vw::chunk("rOBJ", vw::dict({{"_type", "_ground"}})),
                        vw::chunk("rCAM", vw::cat({vw::ints({0}), vw::dict({})})),
                        vw::chunk("NOTE", vw::ints({0})), vw::chunk("IMAP", vw::Bytes(256, 0)),
                        vw::chunk("MATT", vw::ints({1, 0, 0, 0})), vw::chunk("ABCD", {}),
                        vw::chunk("ABCD", {})}));
    Result<VoxImport> r = readVox(bytes, "u.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    ASSERT_EQ(r->warnings.size(), 6u);
    EXPECT_EQ(r->warnings[0], "u.vox: chunk rOBJ (render settings) ignored");
    EXPECT_EQ(r->warnings[1], "u.vox: chunk rCAM (cameras; luxel frames the model itself) ignored");
    EXPECT_EQ(r->warnings[2], "u.vox: chunk NOTE (palette notes) ignored");
    EXPECT_EQ(r->warnings[3], "u.vox: chunk IMAP (palette display order) ignored");
    EXPECT_EQ(r->warnings[4], "u.vox: chunk MATT (old-style materials) ignored");
    EXPECT_NE(r->warnings[5].find("u.vox: unknown chunk 'ABCD' at byte "), std::string::npos);
}

TEST(VoxMaterials, AVoxFileOpensAsAFramedSceneWithItsMaterials) {
    const vw::Bytes bytes = row(3, vw::cat({vw::material(2, {{"_type", "_emit"}, {"_emit", "1"}}),
                                            vw::material(3, {{"_type", "_metal"}})}));
    Result<VoxelScene> scene = voxSceneFromBytes(bytes, "scene.vox", {64, 36});
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->camera.width(), 64);
    EXPECT_EQ(scene->shading.lighting, ShadeOptions::Lighting::Physical);
    ASSERT_EQ(scene->textures.size(), 2);
    EXPECT_EQ(scene->textures[0].name, materialSlotName("vox 2"));
    const int slot = textureSlotOf(scene->world.get(1, 0, 0));
    ASSERT_EQ(slot, 0);
    EXPECT_GT(scene->shading.materials.forSlot(slot).emission.r, 0.0f);
    EXPECT_EQ(scene->shading.materials.forSlot(1).metallic, 1.0f);
    // The camera sees every corner of the world in front of it, inside the image.
    const Int3 s = scene->world.size();
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d c{corner & 1 ? double(s.x) : 0.0, corner & 2 ? double(s.y) : 0.0,
                      corner & 4 ? double(s.z) : 0.0};
        const Vec3d p = scene->camera.position();
        const Vec3d d{c.x - p.x, c.y - p.y, c.z - p.z};
        const Vec3d f = scene->camera.forward(), rt = scene->camera.right(),
                    up = scene->camera.up();
        const double depth = d.x * f.x + d.y * f.y + d.z * f.z;
        ASSERT_GT(depth, 0.0);
        const double tanHalf = std::tan(scene->camera.fovYDegrees() * M_PI / 360.0);
        const double u = (d.x * rt.x + d.y * rt.y + d.z * rt.z) / depth / tanHalf;
        const double v = (d.x * up.x + d.y * up.y + d.z * up.z) / depth / tanHalf;
        EXPECT_LE(std::abs(u), 64.0 / 36.0) << corner;
        EXPECT_LE(std::abs(v), 1.0) << corner;
        EXPECT_GT(p.y, double(s.y));  // from above
    }
}

TEST(VoxMaterials, JsonScenesAppendVoxMaterialsAfterTheirTextures) {
    // A texture of its own takes slot 0; the file's material moves to slot 1.
    const test::TempDir tmp;
    const std::string dir = tmp.dir().string();
    const vw::Bytes bytes = row(2, vw::material(2, {{"_type", "_metal"}}));
    {
        std::FILE* f = std::fopen((dir + "/mat.vox").c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fwrite(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
    }
    const std::string json = R"({"type": "voxel", "materials": [{"name": "stone"}],
      "world": {"source": "vox", "file": "mat.vox", "frame": 0},
      "camera": {"position": [1, 5, -5], "look_at": [1, 0, 0]}})";
    Result<VoxelScene> scene = parseVoxelScene(json, dir + "/scene.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->textures.size(), 2);
    EXPECT_EQ(textureSlotOf(scene->world.get(1, 0, 0)), 1);
    EXPECT_EQ(scene->shading.materials.forSlot(1).metallic, 1.0f);
    EXPECT_EQ(scene->world.get(0, 0, 0).a, kPlainBlockAlpha);
}

}  // namespace
}  // namespace luxel::voxel
