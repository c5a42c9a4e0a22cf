// The scene-file "sky" of voxel scenes, read for voxel_scene.cpp: an analytic sky model,
// {"top", "horizon"} (the default "gradient" model), {"model": "cie-overcast", "zenith"} or
// {"model": "preetham", "turbidity", "zenith"}.
// Format: docs/scene-format-voxel.md.
#pragma once

#include "core/json_fields.h"
#include "luxel/voxel/shading.h"

namespace luxel::voxel {

// Sets options' sky (skyModel and the model's fields) from a scene's "sky" object (fields it
// leaves out keep their values). Throws json::Invalid naming the field.
void readSkyJson(const json::Json& sky, ShadeOptions& options);

}  // namespace luxel::voxel
