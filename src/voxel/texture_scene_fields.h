// The scene-file fields of texture filtering, normal maps and anti-aliasing, read for
// voxel_scene.cpp: "render": {"samples", "adaptive_samples", "adaptive_contrast",
// "texture_filter", "anisotropy", "normal_maps"} and a texture entry's "normal_map". Both throw
// json::Invalid naming the field.
#pragma once

#include <filesystem>
#include <string>

#include "core/json_fields.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {

// The keys readFilterFields reads (for the "render" object's allowed list).
#define LUXEL_VOXEL_FILTER_RENDER_KEYS                                                  \
    "samples", "adaptive_samples", "adaptive_contrast", "texture_filter", "anisotropy", \
        "normal_maps"

// Reads the filtering and anti-aliasing fields of a scene's "render" object into `options`.
void readFilterFields(const json::Json& render, ShadeOptions& options);

// Reads `entry`'s "normal_map" (a PNG relative to baseDir) into texture.normals, if present;
// `path` names the entry in errors ("textures[2]").
void readNormalMapField(const json::Json& entry, const std::string& path,
                        const std::filesystem::path& baseDir, Texture& texture);

}  // namespace luxel::voxel
