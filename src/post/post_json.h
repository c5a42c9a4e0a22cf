// The "post" section of scene files (docs/scene-format-voxel.md), read with the JSON toolkit:
// errors throw json::Invalid naming the field.
#pragma once

#include <string>

#include "core/json_fields.h"
#include "luxel/post/post_options.h"

namespace luxel::post {

// {"bloom": {"strength", "levels", "karis"}, "exposure", "tone", "internal_scale", "upscaler",
//  "sharpness"}; absent fields keep PostOptions' defaults.
PostOptions postOptionsFromJson(const json::Json& v, const std::string& path);

}  // namespace luxel::post
