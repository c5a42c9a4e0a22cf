// Materials: validation naming the field, the table by texture slot, and the scene fields
// ("materials", "render.material", "material" on textures, shapes and texture_by_color rules).
#include "luxel/voxel/material.h"

#include <gtest/gtest.h>

#include <string>

#include "luxel/voxel/voxel_scene.h"
#include "support/temp_dir.h"

namespace luxel::voxel {
namespace {

TEST(Material, DefaultIsARoughDielectric) {
    const Material m = defaultMaterial();
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_GE(m.roughness, 0.5f);
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.transmission, 0.0f);
    EXPECT_TRUE(m.proceduralTexture);
    EXPECT_TRUE(validateMaterial(m).ok());
}

TEST(Material, ValidationNamesTheField) {
    const auto message = [](Material m) {
        m.name = "x";
        const Status s = validateMaterial(m);
        return s.ok() ? std::string("ok") : s.error().message();
    };
    Material m;
    m.roughness = 2.0f;
    EXPECT_EQ(message(m), "material 'x': roughness must be in 0..1, got 2");
    m = Material{};
    m.ior = 0.5f;
    EXPECT_NE(message(m).find("ior must be in 1..4"), std::string::npos);
    m = Material{};
    m.absorption.g = std::nanf("");
    EXPECT_NE(message(m).find("absorption must be in"), std::string::npos);
    m = Material{};
    m.emission.r = -1.0f;
    EXPECT_NE(message(m).find("emission"), std::string::npos);
    m = Material{};
    m.metallic = 1.5f;
    EXPECT_NE(message(m).find("metallic"), std::string::npos);
}

TEST(Material, TableFallsBackToThePlainMaterial) {
    MaterialTable table;
    Material glass;
    glass.name = "glass";
    glass.transmission = 1.0f;
    ASSERT_TRUE(table.setSlot(3, glass).ok());
    EXPECT_EQ(table.forSlot(3).name, "glass");
    EXPECT_TRUE(table.hasSlot(3));
    EXPECT_FALSE(table.hasSlot(2));
    EXPECT_EQ(table.forSlot(2).name, "default");
    EXPECT_EQ(table.forSlot(-1).name, "default");
    EXPECT_EQ(table.forSlot(200).name, "default");
    EXPECT_FALSE(table.setSlot(254, glass).ok());
    glass.roughness = -1.0f;
    EXPECT_FALSE(table.setSlot(0, glass).ok());
    Material rough;
    rough.name = "stone";
    ASSERT_TRUE(table.setPlain(rough).ok());
    EXPECT_EQ(table.forSlot(2).name, "stone");
}

TEST(Material, SceneMaterialsReachShapesRulesTexturesAndPlainBlocks) {
    const test::TempDir tmp;
    const std::string textureDir = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/textures/";
    const std::string path = tmp.write("scene.json", R"({"type": "voxel",
        "materials": [
            {"name": "glass", "ior": 1.5, "transmission": 1, "roughness": 0.02,
             "absorption": [0.2, 0.05, 0.1]},
            {"name": "lamp", "emission": [4, 3, 2]},
            {"name": "stone", "roughness": 0.9},
            {"name": "leafy", "roughness": 0.6}
        ],
        "textures": [{"name": "grass", "file": ")" + textureDir +
                                                         R"(grass.png", "material": "leafy"}],
        "world": {"source": "random", "density": 0.05, "color": [100, 100, 100],
                  "size": [16, 16, 16],
                  "shapes": [
                      {"type": "box", "min": [0, 0, 0], "max": [16, 1, 16], "color": [100, 100, 100]},
                      {"type": "box", "min": [2, 1, 2], "max": [4, 3, 4], "material": "glass"},
                      {"type": "box", "min": [6, 1, 6], "max": [7, 2, 7], "material": "lamp"},
                      {"type": "box", "min": [8, 1, 8], "max": [9, 2, 9], "texture": "grass"}
                  ],
                  "texture_by_color": [{"color": [100, 100, 100], "material": "stone"}]},
        "camera": {"position": [8, 8, -8], "look_at": [8, 0, 8]},
        "render": {"lighting": "physical", "specular": "blinn-phong", "fresnel": "schlick",
                   "refraction": false, "sun_irradiance": [2, 2, 2], "sky_ambient": 0.25,
                   "material": "stone"}})");
    auto scene = loadVoxelScene(path);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const ShadeOptions& o = scene->shading;
    EXPECT_EQ(o.lighting, ShadeOptions::Lighting::Physical);
    EXPECT_EQ(o.specular, ShadeOptions::Specular::BlinnPhong);
    EXPECT_EQ(o.fresnel, ShadeOptions::FresnelModel::Schlick);
    EXPECT_FALSE(o.refraction);
    EXPECT_EQ(o.sunIrradiance, Rgb(2.0f));
    EXPECT_EQ(o.skyAmbient, 0.25f);
    EXPECT_EQ(o.materials.plain().name, "stone");
    const auto materialAt = [&](int x, int y, int z) {
        return o.materials.forSlot(textureSlotOf(scene->world.get(x, y, z)));
    };
    // Shapes with a material: the material's own slot, white, procedural texture on.
    EXPECT_EQ(materialAt(2, 1, 2).name, "glass");
    EXPECT_EQ(materialAt(2, 1, 2).absorption, Rgb(0.2f, 0.05f, 0.1f));
    EXPECT_TRUE(materialAt(2, 1, 2).proceduralTexture);
    EXPECT_EQ(scene->world.get(2, 1, 2).r, 255);
    EXPECT_EQ(materialAt(6, 1, 6).emission, Rgb(4.0f, 3.0f, 2.0f));
    const int glassSlot = textureSlotOf(scene->world.get(2, 1, 2));
    ASSERT_GE(glassSlot, 0);
    EXPECT_EQ(scene->textures[glassSlot].name, "material:glass");
    EXPECT_EQ(scene->textures[glassSlot].width, 1);
    // A texture with a material: the image is the texture.
    EXPECT_EQ(materialAt(8, 1, 8).name, "leafy");
    EXPECT_FALSE(materialAt(8, 1, 8).proceduralTexture);
    // The colour rule gave the random voxels (drawn before the shapes) stone's slot.
    int ruled = 0;
    for (int z = 0; z < 16; ++z) {
        for (int y = 2; y < 16; ++y) {
            for (int x = 0; x < 16; ++x) {
                const Voxel v = scene->world.get(x, y, z);
                if (!v.solid() || v.r != 100) continue;
                const int slot = textureSlotOf(v);
                ASSERT_GE(slot, 0);
                EXPECT_EQ(scene->textures[slot].name, "material:stone");
                ++ruled;
            }
        }
    }
    EXPECT_GT(ruled, 20);
}

TEST(Material, BadSceneMaterialsAreLocated) {
    const test::TempDir tmp;
    struct Case {
        const char* text;
        const char* expected;
    };
    const Case cases[] = {
        {R"({"type": "voxel", "materials": [{"name": "m", "roughness": 3}],
             "world": {"source": "empty", "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0]}})",
         "materials[0].roughness: must be in 0..1"},
        {R"({"type": "voxel", "materials": [{"name": "m", "ior": 0.9}],
             "world": {"source": "empty", "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0]}})",
         "materials[0].ior: must be in 1..4"},
        {R"({"type": "voxel", "materials": [{"name": "m", "shine": 1}],
             "world": {"source": "empty", "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0]}})",
         "unknown field 'shine'"},
        {R"({"type": "voxel", "materials": [{"name": "m"}, {"name": "m"}],
             "world": {"source": "empty", "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0]}})",
         "materials[1].name: duplicate material name 'm'"},
        {R"({"type": "voxel", "materials": [{"roughness": 0.5}],
             "world": {"source": "empty", "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0]}})",
         "materials[0].name: required field is missing"},
        {R"({"type": "voxel", "materials": [{"name": "m", "emission": [1, -1, 0]}],
             "world": {"source": "empty", "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0]}})",
         "materials[0].emission[1]: must be in 0..10000"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8],
             "shapes": [{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "material": "gold"}]},
             "camera": {"position": [0, 0, 0]}})",
         "world.shapes[0].material: unknown material 'gold'"},
        {R"({"type": "voxel", "materials": [{"name": "m"}],
             "world": {"source": "empty", "size": [8, 8, 8]}, "camera": {"position": [0, 0, 0]},
             "render": {"material": "n"}})",
         "render.material: unknown material 'n' (defined: m)"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
             "camera": {"position": [0, 0, 0]}, "render": {"lighting": "pbr"}})",
         "render.lighting: unknown value 'pbr' (known: classic, physical)"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
             "camera": {"position": [0, 0, 0]}, "render": {"specular": "phong"}})",
         "render.specular: unknown value 'phong' (known: none, blinn-phong, ggx)"},
        {R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
             "camera": {"position": [0, 0, 0]}, "render": {"sky_ambient": 2}})",
         "render.sky_ambient: must be in 0..1"},
    };
    int i = 0;
    for (const Case& c : cases) {
        auto scene = loadVoxelScene(tmp.write("bad" + std::to_string(i++) + ".json", c.text));
        ASSERT_FALSE(scene.ok()) << c.expected;
        EXPECT_NE(scene.error().message().find(c.expected), std::string::npos)
            << scene.error().message();
    }
}

}  // namespace
}  // namespace luxel::voxel
