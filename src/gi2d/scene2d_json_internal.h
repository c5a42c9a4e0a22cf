// The 2D scene reader on an already parsed document, for the one scene-file loader
// (luxel/scene/scene_file.h), which reads and parses a file once whatever its type.
#pragma once

#include <string>
#include <string_view>

#include "core/json_fields.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d {

// `text` is the document's source (errors are located in it); `baseDir` resolves image paths.
Result<Scene2D> scene2DFromJson(const json::Json& root, std::string_view text,
                                const std::string& sourceName, const std::string& baseDir);

}  // namespace luxel::gi2d
