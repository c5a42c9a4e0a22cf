// The octree scene reader (docs/scene-format-octree.md) on an already parsed document.
#include "scene/octree_scene_internal.h"

#include <cmath>
#include <filesystem>

#include "luxel/core/timer.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_file.h"
#include "luxel/octree/octree_validate.h"
#include "luxel/octree/volume_generators.h"
#include "voxel/voxel_scene_internal.h"

namespace luxel::scene {
namespace {

using json::find;
using json::Invalid;
using json::Json;

int wholeNumberIn(const Json& v, const std::string& path, int lo, int hi) {
    return static_cast<int>(json::readWholeNumber(v, path, lo, hi));
}

Rgb colourOf(const Json& v, const std::string& path) {
    const auto c = json::readNumbers(v, path, 3, 0, 1e6);
    return Rgb(float(c[0]), float(c[1]), float(c[2]));
}

// The tree described by "octree".
octree::Octree buildTree(const Json& o, const std::filesystem::path& baseDir,
                         std::string& described) {
    json::checkObject(
        o, "octree",
        {"source", "size", "seed", "world", "path", "colours", "attributes", "grid", "max"});
    const Json* sourceJson = find(o, "source");
    if (!sourceJson || !sourceJson->is_string()) {
        throw Invalid{"octree.source",
                      "must be \"phantom\", \"terrain\", \"world\", \"file\" or \"vdb\""};
    }
    const std::string source = sourceJson->get<std::string>();
    const bool colours =
        find(o, "colours") ? json::readBool(*find(o, "colours"), "octree.colours") : true;
    std::optional<octree::AttributeLayout> layout;  // unset: the source's preferred layout
    if (const Json* a = find(o, "attributes")) {
        const std::string name = json::readString(*a, "octree.attributes");
        if (name != "per-entry" && name != "leaf-order") {
            throw Invalid{"octree.attributes", "must be \"per-entry\" or \"leaf-order\""};
        }
        layout = name == "per-entry" ? octree::AttributeLayout::PerEntry
                                     : octree::AttributeLayout::LeafOrder;
    }
    const std::uint64_t seed = find(o, "seed") ? static_cast<std::uint64_t>(json::readWholeNumber(
                                                     *find(o, "seed"), "octree.seed", 0, 1e15))
                                               : 1;
    auto pathOf = [&]() {
        const Json* p = find(o, "path");
        if (!p || !p->is_string()) throw Invalid{"octree.path", "must be a file path"};
        std::filesystem::path file = p->get<std::string>();
        if (file.is_relative()) file = baseDir / file;
        return file.string();
    };
    Result<octree::Octree> tree = Error("");
    if (source == "phantom") {
        const Json* size = find(o, "size");
        const int side =
            size ? wholeNumberIn(*size, "octree.size", 8, octree::kMaxVolumeSide) : 256;
        auto volume = octree::makePhantom(side, seed);
        if (!volume) throw Invalid{"octree.size", volume.error().message()};
        tree = octree::buildOctree(*volume, {.colours = colours, .layout = layout});
        described = "phantom " + std::to_string(side);
    } else if (source == "terrain") {
        const Json* size = find(o, "size");
        const int side =
            size ? wholeNumberIn(*size, "octree.size", 8, 1 << octree::kMaxDepth) : 4096;
        if ((side & (side - 1)) != 0) throw Invalid{"octree.size", "must be a power of two"};
        tree = octree::buildOctree(*octree::makeSparseTerrain(side, seed),
                                   {.colours = colours, .layout = layout});
        described = "terrain " + std::to_string(side);
    } else if (source == "world") {
        const Json* world = find(o, "world");
        if (!world) throw Invalid{"octree", "a \"world\" source needs \"world\": {...}"};
        const voxel::VoxelWorld built = voxel::worldFromJson(*world, baseDir, voxel::TextureSet{});
        tree = octree::buildOctree(built, {.colours = colours, .layout = layout});
        described = "voxel world";
    } else if (source == "file") {
        const std::string file = pathOf();
        tree = octree::readOctreeFile(file);
        described = "file " + file;
        if (tree) return std::move(*tree);
        throw Invalid{"octree.path", tree.error().message()};
    } else if (source == "vdb") {
        const std::string file = pathOf();
        described = "vdb " + file;
        return vdbTreeFromJson(o, file);
    } else {
        throw Invalid{"octree.source",
                      "must be \"phantom\", \"terrain\", \"world\", \"file\" or \"vdb\", got \"" +
                          source + "\""};
    }
    if (!tree) throw Invalid{"octree", tree.error().message()};
    return std::move(*tree);
}

octree::OctreeRenderOptions renderOptions(const Json* r) {
    octree::OctreeRenderOptions o;
    if (!r) return o;
    json::checkObject(
        *r, "render",
        {"mode", "threshold", "opacity_scale", "opacity_window", "shadows", "sun_radius",
         "shadow_samples", "scattering", "albedo", "phase_g", "octaves", "octave_weight",
         "light_cache_stride", "sun_direction", "sun", "sky", "ambient"});
    if (const Json* v = find(*r, "mode")) {
        auto mode = octree::parseOctreeMode(json::readString(*v, "render.mode"), "render.mode");
        if (!mode)
            throw Invalid{"render.mode",
                          "must be \"surface\", \"volume\", \"additive\" or \"tiles\""};
        o.mode = *mode;
    }
    if (const Json* v = find(*r, "threshold")) {
        o.threshold = static_cast<std::uint8_t>(wholeNumberIn(*v, "render.threshold", 1, 255));
    }
    if (const Json* v = find(*r, "opacity_window")) {
        const auto w = json::readNumbers(*v, "render.opacity_window", 2, 0, 255);
        if (w[0] != std::floor(w[0]) || w[1] != std::floor(w[1]) || !(w[0] < w[1])) {
            throw Invalid{"render.opacity_window",
                          "must be [low, high], whole numbers, low < high"};
        }
        o.windowLow = static_cast<std::uint8_t>(w[0]);
        o.windowHigh = static_cast<std::uint8_t>(w[1]);
    }
    if (const Json* v = find(*r, "opacity_scale")) {
        o.opacityScale = float(json::readNumberIn(*v, "render.opacity_scale", 0, 1e6));
    }
    if (const Json* v = find(*r, "shadows")) o.shadows = json::readBool(*v, "render.shadows");
    if (const Json* v = find(*r, "sun_radius")) {
        o.sunRadiusDegrees = float(json::readNumberIn(*v, "render.sun_radius", 0, 45));
    }
    if (const Json* v = find(*r, "shadow_samples")) {
        o.shadowSamples = wholeNumberIn(*v, "render.shadow_samples", 1, 1024);
    }
    if (const Json* v = find(*r, "scattering")) {
        o.scattering = json::readBool(*v, "render.scattering");
    }
    if (const Json* v = find(*r, "albedo")) {
        o.albedo = float(json::readNumberIn(*v, "render.albedo", 0, 1));
    }
    if (const Json* v = find(*r, "phase_g")) {
        o.phaseG = float(json::readNumberIn(*v, "render.phase_g", -0.99, 0.99));
    }
    if (const Json* v = find(*r, "octaves")) o.octaves = wholeNumberIn(*v, "render.octaves", 1, 8);
    if (const Json* v = find(*r, "octave_weight")) {
        o.octaveWeight = float(json::readNumberIn(*v, "render.octave_weight", 0, 1));
    }
    if (const Json* v = find(*r, "light_cache_stride")) {
        o.lightCacheStride = wholeNumberIn(*v, "render.light_cache_stride", -1, 4096);
    }
    if (const Json* v = find(*r, "sun_direction")) {
        const auto d = json::readNumbers(*v, "render.sun_direction", 3, -1, 1);
        if (d[0] == 0 && d[1] == 0 && d[2] == 0) {
            throw Invalid{"render.sun_direction", "must not be [0, 0, 0]"};
        }
        o.sunDirection = {float(d[0]), float(d[1]), float(d[2])};
    }
    if (const Json* v = find(*r, "sun")) o.sun = colourOf(*v, "render.sun");
    if (const Json* v = find(*r, "sky")) o.sky = colourOf(*v, "render.sky");
    if (const Json* v = find(*r, "ambient")) {
        o.ambient = float(json::readNumberIn(*v, "render.ambient", 0, 100));
    }
    return o;
}

}  // namespace

bool isOctreeScene(const json::Json& root) {
    if (!root.is_object()) return false;
    const Json* type = find(root, "type");
    return type && type->is_string() && type->get<std::string>() == "octree";
}

Result<OctreeScene> octreeSceneFromJson(const json::Json& root, std::string_view text,
                                        const std::string& path, int width, int height) {
    try {
        json::checkObject(root, "", {"type", "description", "octree", "camera", "render"});
        const Json* tree = find(root, "octree");
        const Json* camera = find(root, "camera");
        if (!tree) throw Invalid{"", "an octree scene needs \"octree\""};
        if (!camera) throw Invalid{"", "an octree scene needs \"camera\""};
        OctreeScene scene{octree::Octree{},
                          voxel::cameraFromJson(*camera, width, height),
                          renderOptions(find(root, "render")),
                          path,
                          "",
                          0};
        Stopwatch clock;
        scene.tree = buildTree(*tree, std::filesystem::path(path).parent_path(), scene.source);
        scene.buildSeconds = clock.seconds();
        return scene;
    } catch (const Invalid& invalid) {
        return json::locate(invalid, text, path);
    } catch (const std::exception& e) {
        return Error(path + ": " + json::boundMessage(e.what()));
    }
}

}  // namespace luxel::scene
