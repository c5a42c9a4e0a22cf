// Voxel mode's solver: the ray caster, sky visibility (ambient occlusion) or the progressive path
// tracer, by the names `luxel render --solver` gives the latter two (docs/viewer.md).
#pragma once

#include <string_view>

#include "luxel/core/error.h"

namespace luxel::viewer {

enum class VoxelSolver {
    RayCast,        // voxel::render or the GPU ray caster: shading, shadows, reflections
    SkyVisibility,  // voxel::renderSkyVisibility (luxel/voxel/sky_visibility.h)
    PathTrace,      // voxel::PathTracer, accumulated over frames (progressive_path.h)
};
inline constexpr int kVoxelSolverCount = 3;

// "raycast", "ao" or "path"; anything else is an error naming `option` and the choices.
Result<VoxelSolver> parseVoxelSolver(std::string_view text, std::string_view option = "--solver");
// The command-line name ("raycast", "ao", "path").
const char* voxelSolverName(VoxelSolver solver);
// What the panel calls it ("ray caster", "sky visibility (AO)", "path tracer").
const char* voxelSolverLabel(VoxelSolver solver);
// The next in the order above, wrapping (the C key).
VoxelSolver nextVoxelSolver(VoxelSolver solver);

}  // namespace luxel::viewer
