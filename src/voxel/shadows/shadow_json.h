// The scene file's shadow fields: "render": {"shadows": true | false | {...}, "sun_radius": deg}
// (docs/scene-format-voxel.md). Throws json::Invalid naming the field.
#pragma once

#include "core/json_fields.h"
#include "luxel/voxel/shading.h"

namespace luxel::voxel {

// Reads "render.shadows" and "render.sun_radius" into `options` (absent fields keep theirs).
void readShadowJson(const json::Json& render, ShadeOptions& options);

}  // namespace luxel::voxel
