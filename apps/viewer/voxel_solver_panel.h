// Voxel mode's solver controls in the ImGui panel: the solver (C cycles it), the path tracer's
// target and bounces, sky visibility's rays and radius.
#pragma once

#include "renderer_voxel.h"

namespace luxel::viewer {

// Draws the controls; true when one changed. `restart` is set when the change needs the path
// tracer to start over (the target alone does not: it keeps adding, or stops where it is).
bool drawVoxelSolverPanel(VoxelSolverOptions& solver, bool* restart);

}  // namespace luxel::viewer
