// Scene files: JSON in, Scene2D out (and back). The format is documented in
// docs/scene-format-2d.md.
#pragma once

#include <string>
#include <string_view>

#include "luxel/core/error.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d {

// Reads and validates a scene file. Image layers are loaded relative to the file's folder.
// Errors name the file, line:column and field, e.g.
//   "scenes/2d/room.json:12:17: shapes[3].radius: must be > 0, got -4".
Result<Scene2D> loadScene2D(const std::string& path);

// Same, from text. `sourceName` is used in messages, `baseDir` resolves image paths.
Result<Scene2D> parseScene2D(std::string_view text, const std::string& sourceName,
                             const std::string& baseDir);

// Writes a scene back as JSON text (image layers by their paths as written). parseScene2D of the
// result gives an equal scene.
std::string sceneToJson(const Scene2D& scene);

}  // namespace luxel::gi2d
