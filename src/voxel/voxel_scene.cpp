// Voxel scene files: JSON -> world + camera + shading options, with located errors.
#include "luxel/voxel/voxel_scene.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/json_fields.h"
#include "luxel/core/file_io.h"
#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/generators.h"
#include "luxel/voxel/vox_import.h"
#include "luxel/voxel/vox_scene.h"
#include "post/post_json.h"
#include "voxel/material_scene.h"
#include "voxel/shadows/shadow_json.h"
#include "voxel/sky_scene.h"
#include "voxel/texture_scene_fields.h"
#include "voxel/voxel_scene_internal.h"

namespace luxel::voxel {
namespace {

// The one JSON toolkit (core/json_fields.h): typed reads, one wording, located errors.
using namespace json;

int wholeNumber(const Json& v, const std::string& path, int lo, int hi) {
    return static_cast<int>(readWholeNumber(v, path, lo, hi));
}

Voxel colourOf(const Json& v, const std::string& path) {
    const auto c = readNumbers(v, path, 3, 0, 255);
    return {static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
            static_cast<std::uint8_t>(c[2]), 255};
}

// Reads "textures": PNG files relative to the scene, each with a name shapes refer to.
TextureSet buildTextures(const Json* list, const std::filesystem::path& baseDir,
                         const std::vector<Material>& materials, MaterialTable& table) {
    TextureSet set;
    if (!list) return set;
    if (!list->is_array()) throw Invalid{"textures", "must be an array"};
    if (list->size() > static_cast<std::size_t>(kMaxTextures)) {
        throw Invalid{"textures", "has " + std::to_string(list->size()) + " entries, at most " +
                                      std::to_string(kMaxTextures) +
                                      " (voxel alpha 1..254 selects one)"};
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
        const Json& t = (*list)[i];
        const std::string path = "textures[" + std::to_string(i) + "]";
        checkObject(t, path, {"name", "file", "reflectivity", "material", "normal_map"});
        const Json* name = find(t, "name");
        if (!name || !name->is_string() || name->get<std::string>().empty()) {
            throw Invalid{path + ".name", "must be a non-empty string"};
        }
        const Json* file = find(t, "file");
        if (!file || !file->is_string()) throw Invalid{path + ".file", "must be a PNG path"};
        std::filesystem::path p = file->get<std::string>();
        if (p.is_relative()) p = baseDir / p;
        Result<Texture> texture = TextureSet::load(name->get<std::string>(), p.string());
        if (!texture) throw Invalid{path + ".file", texture.error().message()};
        readNormalMapField(t, path, baseDir, *texture);
        if (const Json* v = find(t, "reflectivity")) {
            texture->reflectivity =
                static_cast<float>(readNumberIn(*v, path + ".reflectivity", 0, 1));
        }
        Result<int> slot = set.add(std::move(*texture));
        if (!slot) throw Invalid{path + ".name", slot.error().message()};
        if (const Json* m = find(t, "material")) {
            const std::string field = path + ".material";
            Material material = findMaterial(materials, readString(*m, field), field);
            material.proceduralTexture = false;  // the image is the texture
            if (Status st = table.setSlot(*slot, std::move(material)); !st) {
                throw Invalid{field, st.error().message()};
            }
        }
    }
    return set;
}

// The alpha byte of a texture named at `path` (a plain block when there is no such field).
std::uint8_t materialAlpha(const Json& object, const std::string& path,
                           const TextureSet& textures) {
    const Json* name = find(object, "texture");
    // A material without an image is the texture slot named after it (material.h).
    if (const Json* material = find(object, "material")) {
        if (name) throw Invalid{path + ".material", "give \"texture\" or \"material\", not both"};
        const std::string field = path + ".material";
        const std::string materialName = readString(*material, field);
        if (const std::optional<int> slot = textures.find(materialSlotName(materialName))) {
            return alphaForSlot(*slot);
        }
        throw Invalid{field, "unknown material '" + materialName + "'"};
    }
    if (!name) return kPlainBlockAlpha;
    if (!name->is_string()) throw Invalid{path + ".texture", "must be a texture name"};
    const std::optional<int> slot = textures.find(name->get<std::string>());
    if (!slot) {
        std::string known;
        for (int i = 0; i < textures.size(); ++i) {
            known += (known.empty() ? "" : ", ") + textures[i].name;
        }
        throw Invalid{path + ".texture", "unknown texture '" + name->get<std::string>() +
                                             "' (defined: " + (known.empty() ? "none" : known) +
                                             ")"};
    }
    return alphaForSlot(*slot);
}

// "texture_by_color": plain blocks within `tolerance` (per channel) of a colour get a texture.
// Terrain band colours are jittered by up to 8 per channel, hence the tolerance.
void textureByColour(const Json& list, VoxelWorld& world, const TextureSet& textures) {
    if (!list.is_array()) throw Invalid{"world.texture_by_color", "must be an array"};
    struct Rule {
        Voxel colour;
        int tolerance;
        std::uint8_t alpha;
    };
    std::vector<Rule> rules;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "world.texture_by_color[" + std::to_string(i) + "]";
        checkObject(list[i], path, {"color", "tolerance", "texture", "material"});
        const Json* colour = find(list[i], "color");
        if (!colour) throw Invalid{path, "needs \"color\": [r, g, b]"};
        if (!find(list[i], "texture") && !find(list[i], "material")) {
            throw Invalid{path, "needs \"texture\" or \"material\": name"};
        }
        const Json* tolerance = find(list[i], "tolerance");
        rules.push_back({colourOf(*colour, path + ".color"),
                         tolerance ? wholeNumber(*tolerance, path + ".tolerance", 0, 255) : 0,
                         materialAlpha(list[i], path, textures)});
    }
    const Int3 size = world.size();
    for (int z = 0; z < size.z; ++z) {
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                Voxel v = world.get(x, y, z);
                if (v.a != kPlainBlockAlpha) continue;
                for (const Rule& rule : rules) {
                    const auto near = [&](std::uint8_t a, std::uint8_t b) {
                        return std::abs(int(a) - int(b)) <= rule.tolerance;
                    };
                    if (near(v.r, rule.colour.r) && near(v.g, rule.colour.g) &&
                        near(v.b, rule.colour.b)) {
                        v.a = rule.alpha;
                        world.set(x, y, z, v);
                        break;
                    }
                }
            }
        }
    }
}

// A "vox" source: the file's world, its materials and warnings given to the scene.
Result<VoxelWorld> voxWorld(const std::string& path, int chunk, const Json& w,
                            const VoxWorldExtras& extras) {
    int frame = 0;
    if (const Json* f = find(w, "frame")) frame = wholeNumber(*f, "world.frame", 0, 1 << 30);
    if (extras.voxFrame >= 0) frame = extras.voxFrame;
    const bool keepMaterials = extras.textures && extras.table;
    Result<VoxImport> import = readVoxFile(path, {chunk, frame, keepMaterials});
    if (!import) return import.error();
    if (!keepMaterials) return std::move(import->world);
    if (Status s = addVoxMaterials(*import, *extras.textures, *extras.table); !s) {
        return Error(path + ": " + s.error().message());
    }
    if (extras.warnings) {
        extras.warnings->insert(extras.warnings->end(), import->warnings.begin(),
                                import->warnings.end());
    }
    return std::move(import->world);
}

}  // namespace

// Builds the world described by "world".
VoxelWorld worldFromJson(const Json& w, const std::filesystem::path& baseDir,
                         const TextureSet& textures, const VoxWorldExtras& voxExtras) {
    checkObject(
        w, "world",
        {"source", "size", "chunk", "seed", "height", "amplitude", "frequency", "octaves", "water",
         "caves", "density", "color", "file", "shapes", "texture_by_color", "frame"});
    const Json* sourceJson = find(w, "source");
    if (!sourceJson || !sourceJson->is_string()) {
        throw Invalid{"world.source", "must be \"terrain\", \"random\", \"empty\" or \"vox\""};
    }
    const std::string source = sourceJson->get<std::string>();
    const int chunk = find(w, "chunk") ? wholeNumber(*find(w, "chunk"), "world.chunk", 4, 128) : 32;

    auto result = [&]() -> Result<VoxelWorld> {
        if (source == "vox") {
            const Json* file = find(w, "file");
            if (!file || !file->is_string()) throw Invalid{"world.file", "must be a .vox path"};
            std::filesystem::path p = file->get<std::string>();
            if (p.is_relative()) p = baseDir / p;
            return voxWorld(p.string(), chunk, w, voxExtras);
        }
        const Json* sizeJson = find(w, "size");
        if (!sizeJson) throw Invalid{"world", "needs \"size\": [x, y, z]"};
        const auto s = readNumbers(*sizeJson, "world.size", 3, 1, kMaxWorldSide);
        for (int a = 0; a < 3; ++a) {
            if (s[a] != std::floor(s[a])) throw Invalid{"world.size", "must be whole numbers"};
        }
        return VoxelWorld::create(
            {static_cast<int>(s[0]), static_cast<int>(s[1]), static_cast<int>(s[2])}, chunk);
    }();
    if (!result)
        throw Invalid{source == "vox" ? "world.file" : "world.size", result.error().message()};
    VoxelWorld world = std::move(*result);

    const std::uint64_t seed =
        find(w, "seed")
            ? static_cast<std::uint64_t>(wholeNumber(*find(w, "seed"), "world.seed", 0, 2147483647))
            : 1;
    Status status = Ok{};
    if (source == "terrain") {
        TerrainOptions t;
        t.seed = seed;
        if (auto* v = find(w, "height")) t.baseHeight = readNumberIn(*v, "world.height", 0, 1);
        if (auto* v = find(w, "amplitude")) t.amplitude = readNumberIn(*v, "world.amplitude", 0, 1);
        if (auto* v = find(w, "frequency")) t.frequency = readNumberIn(*v, "world.frequency", 0, 1);
        if (auto* v = find(w, "octaves")) t.octaves = wholeNumber(*v, "world.octaves", 1, 16);
        if (auto* v = find(w, "water")) t.waterLevel = readNumberIn(*v, "world.water", 0, 1);
        if (auto* v = find(w, "caves")) {
            if (!v->is_boolean()) throw Invalid{"world.caves", "must be true or false"};
            t.caves = v->get<bool>();
        }
        status = generateTerrain(world, t);
    } else if (source == "random") {
        const Json* d = find(w, "density");
        const double density = d ? readNumberIn(*d, "world.density", 0, 1) : 0.1;
        std::optional<Voxel> colour;
        if (auto* c = find(w, "color")) colour = colourOf(*c, "world.color");
        status = fillRandom(world, density, seed, colour);
    } else if (source != "empty" && source != "vox") {
        throw Invalid{"world.source",
                      "unknown world source '" + source + "' (known: terrain, random, empty, vox)"};
    }
    if (!status) throw Invalid{"world", status.error().message()};
    if (const Json* rules = find(w, "texture_by_color")) {
        textureByColour(*rules, world, textures);
    }

    if (const Json* shapes = find(w, "shapes")) {
        if (!shapes->is_array()) throw Invalid{"world.shapes", "must be an array"};
        for (std::size_t i = 0; i < shapes->size(); ++i) {
            const Json& s = (*shapes)[i];
            const std::string path = "world.shapes[" + std::to_string(i) + "]";
            checkObject(s, path,
                        {"type", "center", "radius", "min", "max", "color", "texture", "material"});
            const Json* type = find(s, "type");
            const Json* colourJson = find(s, "color");
            const std::uint8_t alpha = materialAlpha(s, path, textures);
            // Textured shapes (and materials) default to white, so the texture and the
            // material's albedo show their own colours.
            Voxel colour = colourJson                  ? colourOf(*colourJson, path + ".color")
                           : alpha == kPlainBlockAlpha ? Voxel{200, 200, 200, 255}
                                                       : Voxel{255, 255, 255, 255};
            colour.a = alpha;
            const std::string t = type && type->is_string() ? type->get<std::string>() : "";
            if (t == "sphere") {
                if (!find(s, "center") || !find(s, "radius")) {
                    throw Invalid{path, "a sphere needs \"center\" and \"radius\""};
                }
                const auto c = readNumbers(*find(s, "center"), path + ".center", 3, -1e6, 1e6);
                const double radius = readNumberIn(*find(s, "radius"), path + ".radius", 0, 1e5);
                addSphere(
                    world,
                    {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])},
                    static_cast<float>(radius), colour);
            } else if (t == "box") {
                if (!find(s, "min") || !find(s, "max")) {
                    throw Invalid{path, "a box needs \"min\" and \"max\""};
                }
                const auto lo = readNumbers(*find(s, "min"), path + ".min", 3, -1e6, 1e6);
                const auto hi = readNumbers(*find(s, "max"), path + ".max", 3, -1e6, 1e6);
                addBox(world,
                       {static_cast<int>(lo[0]), static_cast<int>(lo[1]), static_cast<int>(lo[2])},
                       {static_cast<int>(hi[0]), static_cast<int>(hi[1]), static_cast<int>(hi[2])},
                       colour);
            } else {
                throw Invalid{path + ".type",
                              "unknown shape type '" + t + "' (known: sphere, box)"};
            }
        }
    }
    return world;
}

Camera cameraFromJson(const Json& c, int width, int height) {
    checkObject(c, "camera", {"position", "yaw", "pitch", "look_at", "fov", "size"});
    const Json* pos = find(c, "position");
    if (!pos) throw Invalid{"camera", "needs \"position\": [x, y, z]"};
    const auto p = readNumbers(*pos, "camera.position", 3, -1e6, 1e6);
    const double fov = find(c, "fov") ? readNumberIn(*find(c, "fov"), "camera.fov", 1, 179) : 60;
    int w = 960, h = 540;
    if (const Json* size = find(c, "size")) {
        const auto s = readNumbers(*size, "camera.size", 2, 1, kMaxCameraSide);
        w = static_cast<int>(s[0]);
        h = static_cast<int>(s[1]);
    }
    if (width > 0) w = width;
    if (height > 0) h = height;
    Result<Camera> camera = Error("");
    if (const Json* target = find(c, "look_at")) {
        const auto t = readNumbers(*target, "camera.look_at", 3, -1e6, 1e6);
        camera = Camera::lookAt({p[0], p[1], p[2]}, {t[0], t[1], t[2]}, fov, w, h);
    } else {
        const double yaw =
            find(c, "yaw") ? readNumberIn(*find(c, "yaw"), "camera.yaw", -360, 360) : 0;
        const double pitch =
            find(c, "pitch") ? readNumberIn(*find(c, "pitch"), "camera.pitch", -90, 90) : 0;
        camera = Camera::create({p[0], p[1], p[2]}, yaw, pitch, fov, w, h);
    }
    if (!camera) throw Invalid{"camera", camera.error().message()};
    return *camera;
}

namespace {

// The physical-lighting fields of "render" (docs/algorithms/voxel-surfaces.md).
void readSurfaceOptions(const Json& render, const std::vector<Material>& materials,
                        ShadeOptions& o) {
    const auto choice = [&](const char* key, std::initializer_list<const char*> names) {
        const Json* v = find(render, key);
        if (!v) return -1;
        const std::string field = std::string("render.") + key;
        const std::string text = readString(*v, field);
        std::string known;
        int i = 0;
        for (const char* name : names) {
            if (text == name) return i;
            known += (i++ ? ", " : "") + std::string(name);
        }
        throw Invalid{field, "unknown value '" + text + "' (known: " + known + ")"};
    };
    if (int i = choice("lighting", {"classic", "physical"}); i >= 0) {
        o.lighting = i == 0 ? ShadeOptions::Lighting::Classic : ShadeOptions::Lighting::Physical;
    }
    if (int i = choice("specular", {"none", "blinn-phong", "ggx"}); i >= 0) {
        o.specular = static_cast<ShadeOptions::Specular>(i);
    }
    if (int i = choice("fresnel", {"schlick", "exact"}); i >= 0) {
        o.fresnel = static_cast<ShadeOptions::FresnelModel>(i);
    }
    if (const Json* v = find(render, "refraction"))
        o.refraction = readBool(*v, "render.refraction");
    if (const Json* v = find(render, "sun_irradiance")) {
        const auto c = readNumbers(*v, "render.sun_irradiance", 3, 0, 1e4);
        o.sunIrradiance = {float(c[0]), float(c[1]), float(c[2])};
    }
    if (const Json* v = find(render, "sky_ambient")) {
        o.skyAmbient = static_cast<float>(readNumberIn(*v, "render.sky_ambient", 0, 1));
    }
    if (const Json* v = find(render, "sky_ambient_rays")) {
        o.skyAmbientRays = wholeNumber(*v, "render.sky_ambient_rays", 0, kMaxSkyAmbientRays);
    }
    if (const Json* v = find(render, "emitter_light")) {
        o.emitterLight = readBool(*v, "render.emitter_light");
    }
    if (const Json* v = find(render, "emitter_rays")) {
        o.emitterRays = wholeNumber(*v, "render.emitter_rays", 1, kMaxEmitterRays);
    }
    if (const Json* v = find(render, "material")) {
        Material m = findMaterial(materials, readString(*v, "render.material"), "render.material");
        m.proceduralTexture = true;
        if (Status st = o.materials.setPlain(std::move(m)); !st) {
            throw Invalid{"render.material", st.error().message()};
        }
    }
}

ShadeOptions buildShading(const Json& root, const std::vector<Material>& materials,
                          MaterialTable table) {
    ShadeOptions o;
    o.materials = std::move(table);
    if (const Json* sun = find(root, "sun")) {
        const auto s = readNumbers(*sun, "sun", 3, -1e3, 1e3);
        if (s[0] == 0 && s[1] == 0 && s[2] == 0) throw Invalid{"sun", "must not be zero"};
        o.sunDirection = {static_cast<float>(s[0]), static_cast<float>(s[1]),
                          static_cast<float>(s[2])};
    }
    if (const Json* sky = find(root, "sky")) readSkyJson(*sky, o);
    if (const Json* render = find(root, "render")) {
        checkObject(*render, "render",
                    {"reflections", "reflection_mode", "reflectivity", "shadows", "textures",
                     "lighting", "specular", "fresnel", "refraction", "sun_irradiance",
                     "sky_ambient", "sky_ambient_rays", "material", "sun_radius", "emitter_light",
                     "emitter_rays", LUXEL_VOXEL_FILTER_RENDER_KEYS});
        readSurfaceOptions(*render, materials, o);
        readFilterFields(*render, o);
        if (auto* v = find(*render, "reflections")) {
            o.maxReflections = wholeNumber(*v, "render.reflections", 0, 16);
        }
        if (auto* v = find(*render, "reflectivity")) {
            o.reflectivity = static_cast<float>(readNumberIn(*v, "render.reflectivity", 0, 1));
        }
        if (auto* v = find(*render, "reflection_mode")) {
            const std::string m = v->is_string() ? v->get<std::string>() : "";
            if (m == "running-average") {
                o.reflectionMode = ShadeOptions::ReflectionMode::RunningAverage;
            } else if (m == "energy") {
                o.reflectionMode = ShadeOptions::ReflectionMode::EnergyConserving;
            } else {
                throw Invalid{"render.reflection_mode",
                              "must be \"running-average\" or \"energy\""};
            }
        }
        if (const Json* v = find(*render, "textures")) {
            if (!v->is_boolean()) throw Invalid{"render.textures", "must be true or false"};
            o.textures = v->get<bool>();
        }
        readShadowJson(*render, o);
    }
    return o;
}

}  // namespace

bool isVoxelScene(const json::Json& root) {
    if (!root.is_object()) return false;
    const Json* type = find(root, "type");
    return type && type->is_string() && type->get<std::string>() == "voxel";
}

Result<VoxelScene> loadVoxelScene(const std::string& path, int width, int height) {
    auto text = readFileBytes(path, "scene");
    if (!text) return text.error();
    return parseVoxelScene(*text, path, width, height);
}

Result<VoxelScene> parseVoxelScene(std::string_view text, const std::string& path, int width,
                                   int height) {
    auto root = json::parse(text, path);
    if (!root) return root.error();
    return voxelSceneFromJson(*root, text, path, width, height);
}

Result<VoxelScene> voxelSceneFromJson(const json::Json& root, std::string_view text,
                                      const std::string& path, int width, int height,
                                      int voxFrame) {
    try {
        checkObject(root, "",
                    {"type", "description", "textures", "world", "camera", "sun", "sky", "render",
                     "materials", "post"});
        const Json* world = find(root, "world");
        const Json* camera = find(root, "camera");
        if (!world) throw Invalid{"", "a voxel scene needs \"world\""};
        if (!camera) throw Invalid{"", "a voxel scene needs \"camera\""};
        const std::filesystem::path baseDir = std::filesystem::path(path).parent_path();
        const std::vector<Material> materials = materialsFromJson(find(root, "materials"));
        MaterialTable table;
        TextureSet textures = buildTextures(find(root, "textures"), baseDir, materials, table);
        addMaterialSlots(materials, textures, table);
        std::vector<std::string> warnings;
        VoxelWorld built =
            worldFromJson(*world, baseDir, textures, {&textures, &table, &warnings, voxFrame});
        VoxelScene scene{std::move(built),
                         cameraFromJson(*camera, width, height),
                         buildShading(root, materials, std::move(table)),
                         path,
                         std::move(textures),
                         {},
                         std::move(warnings)};
        if (const Json* p = find(root, "post")) scene.post = post::postOptionsFromJson(*p, "post");
        if (const Json* render = find(root, "render");
            render && find(*render, "sky_ambient") && scene.shading.skyAmbientRays > 0) {
            // The traced sky replaces the assumed share (docs/algorithms/voxel-surfaces.md).
            scene.warnings.push_back(path +
                                     ": render.sky_ambient is not used: render.sky_ambient_rays "
                                     "traces the sky the faces see");
        }
        return scene;
    } catch (const Invalid& invalid) {
        return json::locate(invalid, text, path);
    } catch (const std::exception& e) {
        return Error(path + ": " + json::boundMessage(e.what()));
    }
}

}  // namespace luxel::voxel
