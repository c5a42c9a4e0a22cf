// Scene-file fields of texture filtering, normal maps and anti-aliasing.
#include "voxel/texture_scene_fields.h"

#include "luxel/voxel/render_image.h"

namespace luxel::voxel {

using namespace json;

void readFilterFields(const Json& render, ShadeOptions& options) {
    if (const Json* v = find(render, "samples")) {
        options.samplesPerPixel =
            static_cast<int>(readWholeNumber(*v, "render.samples", 1, kMaxSamplesPerPixel));
    }
    // The radiance cascades' adaptive pass (src/voxel/cascades/adaptive_samples.h): 0 turns it
    // off.
    if (const Json* v = find(render, "adaptive_samples")) {
        options.adaptiveSamples = static_cast<int>(
            readWholeNumber(*v, "render.adaptive_samples", 0, kMaxSamplesPerPixel));
    }
    if (const Json* v = find(render, "adaptive_contrast")) {
        options.adaptiveContrast = readNumberIn(*v, "render.adaptive_contrast", 1e-3, 1e6);
    }
    if (const Json* v = find(render, "texture_filter")) {
        const std::optional<TextureFilter> f =
            parseTextureFilter(v->is_string() ? v->get<std::string>() : "");
        if (!f) {
            throw Invalid{"render.texture_filter",
                          "must be \"nearest\", \"trilinear\" or \"anisotropic\""};
        }
        options.textureFilter = *f;
    }
    if (const Json* v = find(render, "anisotropy")) {
        options.maxAnisotropy = static_cast<int>(readWholeNumber(*v, "render.anisotropy", 1, 64));
    }
    if (const Json* v = find(render, "normal_maps")) {
        options.normalMaps = readBool(*v, "render.normal_maps");
    }
}

void readNormalMapField(const Json& entry, const std::string& path,
                        const std::filesystem::path& baseDir, Texture& texture) {
    const Json* file = find(entry, "normal_map");
    if (!file) return;
    if (!file->is_string()) throw Invalid{path + ".normal_map", "must be a PNG path"};
    std::filesystem::path p = file->get<std::string>();
    if (p.is_relative()) p = baseDir / p;
    if (Status s = TextureSet::loadNormalMap(texture, p.string()); !s) {
        throw Invalid{path + ".normal_map", s.error().message()};
    }
}

}  // namespace luxel::voxel
