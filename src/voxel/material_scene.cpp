// Materials from scene files (material_scene.h).
#include "voxel/material_scene.h"

namespace luxel::voxel {

using namespace json;

namespace {

Rgb rgbOf(const Json& v, const std::string& path, double hi) {
    const auto c = readNumbers(v, path, 3, 0, hi);
    return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

float numberOf(const Json& v, const std::string& path, double lo, double hi) {
    return static_cast<float>(readNumberIn(v, path, lo, hi));
}

Material materialFromJson(const Json& j, const std::string& path) {
    checkObject(j, path,
                {"name", "albedo", "metallic", "roughness", "ior", "transmission", "absorption",
                 "emission"});
    Material m;
    m.name = readString(require(j, path, "name"), member(path, "name"));
    if (m.name.empty()) fail(member(path, "name"), "must not be empty");
    if (const Json* v = find(j, "albedo")) m.albedo = rgbOf(*v, member(path, "albedo"), 1);
    if (const Json* v = find(j, "metallic"))
        m.metallic = numberOf(*v, member(path, "metallic"), 0, 1);
    if (const Json* v = find(j, "roughness")) {
        m.roughness = numberOf(*v, member(path, "roughness"), 0, 1);
    }
    if (const Json* v = find(j, "ior")) m.ior = numberOf(*v, member(path, "ior"), 1, 4);
    if (const Json* v = find(j, "transmission")) {
        m.transmission = numberOf(*v, member(path, "transmission"), 0, 1);
    }
    if (const Json* v = find(j, "absorption")) {
        m.absorption = rgbOf(*v, member(path, "absorption"), 1e3);
    }
    if (const Json* v = find(j, "emission")) m.emission = rgbOf(*v, member(path, "emission"), 1e4);
    return m;
}

}  // namespace

std::vector<Material> materialsFromJson(const Json* list) {
    std::vector<Material> materials;
    if (!list) return materials;
    requireArray(*list, "materials");
    for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string path = element("materials", i);
        Material m = materialFromJson((*list)[i], path);
        for (const Material& other : materials) {
            if (other.name == m.name) {
                fail(member(path, "name"), "duplicate material name '" + m.name + "'");
            }
        }
        materials.push_back(std::move(m));
    }
    return materials;
}

const Material& findMaterial(const std::vector<Material>& materials, const std::string& name,
                             const std::string& path) {
    std::string known;
    for (const Material& m : materials) {
        if (m.name == name) return m;
        known += (known.empty() ? "" : ", ") + m.name;
    }
    fail(path,
         "unknown material '" + name + "' (defined: " + (known.empty() ? "none" : known) + ")");
}

void addMaterialSlots(const std::vector<Material>& materials, TextureSet& textures,
                      MaterialTable& table) {
    for (std::size_t i = 0; i < materials.size(); ++i) {
        Texture white;
        white.name = materialSlotName(materials[i].name);
        white.width = white.height = 1;
        white.texels = {Texel{}};
        Result<int> slot = textures.add(std::move(white));
        if (!slot) fail(element("materials", i), slot.error().message());
        Material m = materials[i];
        m.proceduralTexture = true;
        if (Status s = table.setSlot(*slot, std::move(m)); !s) {
            fail(element("materials", i), s.error().message());
        }
    }
}

}  // namespace luxel::voxel
