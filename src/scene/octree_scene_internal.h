// The octree scene reader on an already parsed document, for loadSceneFile.
#pragma once

#include <string>
#include <string_view>

#include "core/json_fields.h"
#include "luxel/scene/octree_scene.h"

namespace luxel::scene {

// Whether a parsed scene document declares "type": "octree".
bool isOctreeScene(const json::Json& root);

Result<OctreeScene> octreeSceneFromJson(const json::Json& root, std::string_view text,
                                        const std::string& path, int width = 0, int height = 0);

// The tree of a "vdb" source (the "octree" object `o`, its file at `path`); throws json::Invalid
// naming the field.
octree::Octree vdbTreeFromJson(const json::Json& o, const std::string& path);

}  // namespace luxel::scene
