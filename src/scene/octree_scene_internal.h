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

// An OpenVDB grid as an octree (the "vdb" source); an error naming why when luxel was built
// without OpenVDB.
Result<octree::Octree> importVdbForScene(const std::string& path, bool colours);

}  // namespace luxel::scene
