// Voxel mode's solver: the ray caster, sky visibility (ambient occlusion), the progressive path
// tracer or radiance cascades, by the names `luxel render --solver` gives them (docs/viewer.md).
#pragma once

#include <string_view>

#include "luxel/core/error.h"

namespace luxel::viewer {

enum class VoxelSolver {
    RayCast,        // voxel::render or the GPU ray caster: shading, shadows, reflections
    SkyVisibility,  // voxel::renderSkyVisibility (luxel/voxel/sky_visibility.h)
    PathTrace,      // voxel::PathTracer, accumulated over frames (progressive_path.h)
    Cascades,       // voxel::RadianceCascades, one more reflection each frame
};
inline constexpr int kVoxelSolverCount = 4;

// "raycast", "ao", "path" or "rc"; anything else is an error naming `option` and the choices.
Result<VoxelSolver> parseVoxelSolver(std::string_view text, std::string_view option = "--solver");
// The command-line name ("raycast", "ao", "path", "rc").
const char* voxelSolverName(VoxelSolver solver);
// What the panel calls it ("ray caster", "sky visibility (AO)", "path tracer", "radiance
// cascades").
const char* voxelSolverLabel(VoxelSolver solver);
// The next in the order above, wrapping (the C key).
VoxelSolver nextVoxelSolver(VoxelSolver solver);

}  // namespace luxel::viewer
