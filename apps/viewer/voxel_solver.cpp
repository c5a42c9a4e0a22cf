// Voxel mode's solver names.
#include "voxel_solver.h"

#include <string>

namespace luxel::viewer {

Result<VoxelSolver> parseVoxelSolver(std::string_view text, std::string_view option) {
    for (int i = 0; i < kVoxelSolverCount; ++i) {
        const auto solver = static_cast<VoxelSolver>(i);
        if (text == voxelSolverName(solver)) return solver;
    }
    return Error(std::string(option) + " '" + std::string(text) +
                 "' is not a voxel solver: raycast, ao, path or rc");
}

const char* voxelSolverName(VoxelSolver solver) {
    switch (solver) {
        case VoxelSolver::RayCast:
            return "raycast";
        case VoxelSolver::SkyVisibility:
            return "ao";
        case VoxelSolver::PathTrace:
            return "path";
        case VoxelSolver::Cascades:
            return "rc";
    }
    return "?";
}

const char* voxelSolverLabel(VoxelSolver solver) {
    switch (solver) {
        case VoxelSolver::RayCast:
            return "ray caster";
        case VoxelSolver::SkyVisibility:
            return "sky visibility (AO)";
        case VoxelSolver::PathTrace:
            return "path tracer";
        case VoxelSolver::Cascades:
            return "radiance cascades";
    }
    return "?";
}

VoxelSolver nextVoxelSolver(VoxelSolver solver) {
    return static_cast<VoxelSolver>((static_cast<int>(solver) + 1) % kVoxelSolverCount);
}

}  // namespace luxel::viewer
