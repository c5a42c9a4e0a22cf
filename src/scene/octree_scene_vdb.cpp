// The "vdb" octree source. OpenVDB import lives in its own library (luxel_octree_vdb); until it is
// linked here, a vdb source is refused with the reason.
#include "scene/octree_scene_internal.h"

namespace luxel::scene {

Result<octree::Octree> importVdbForScene(const std::string& path, bool) {
    return Error(path + ": this luxel was built without OpenVDB import");
}

}  // namespace luxel::scene
