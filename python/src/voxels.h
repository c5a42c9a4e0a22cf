// Voxel worlds, cameras and scenes as Python objects (voxels.cpp).
#pragma once

#include "bindings.h"
#include "luxel/core/vec.h"

namespace luxel::python {

// (x, y, z) from a sequence of three finite numbers; `what` names it in errors.
Vec3d vec3From(py::handle value, const char* what);

}  // namespace luxel::python
