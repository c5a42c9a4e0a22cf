// Scene-file reading of materials ("materials", "render.material", the "material" field of
// textures, shapes and texture_by_color rules). Format: docs/scene-format-voxel.md.
#pragma once

#include <string>
#include <vector>

#include "core/json_fields.h"
#include "luxel/voxel/material.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {

// The top-level "materials" array (absent: none). Throws json::Invalid naming the field.
std::vector<Material> materialsFromJson(const json::Json* list);

// The material called `name` (field `path` names where it was asked for).
const Material& findMaterial(const std::vector<Material>& materials, const std::string& name,
                             const std::string& path);

// Gives every material without an image its own texture slot ("material:NAME", one white texel)
// and the table entry for it, with the procedural texture on.
void addMaterialSlots(const std::vector<Material>& materials, TextureSet& textures,
                      MaterialTable& table);

}  // namespace luxel::voxel
