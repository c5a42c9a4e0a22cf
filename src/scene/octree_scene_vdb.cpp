// The "vdb" octree source (docs/scene-format-octree.md §1): `path`, and optionally `grid` and
// `max`, read into VdbImportOptions for importVdb (luxel/octree/octree_vdb.h).
#include "luxel/octree/octree_vdb.h"
#include "scene/octree_scene_internal.h"

namespace luxel::scene {

octree::Octree vdbTreeFromJson(const json::Json& o, const std::string& path) {
    octree::VdbImportOptions options;
    if (const json::Json* grid = json::find(o, "grid")) {
        options.grid = json::readString(*grid, "octree.grid");
        if (options.grid.empty()) throw json::Invalid{"octree.grid", "must not be empty"};
    }
    if (const json::Json* max = json::find(o, "max")) {
        options.max = static_cast<float>(json::readNumberIn(*max, "octree.max", 1e-30, 1e30));
    }
    auto tree = octree::importVdb(path, options);
    if (!tree) throw json::Invalid{"octree.path", tree.error().message()};
    return std::move(*tree);
}

}  // namespace luxel::scene
