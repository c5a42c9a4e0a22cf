// Voxel mode's solver controls (voxel_solver_panel.h).
#include "voxel_solver_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace luxel::viewer {

bool drawVoxelSolverPanel(VoxelSolverOptions& solver, bool* restart) {
    bool touched = false;
    int kind = static_cast<int>(solver.kind);
    const char* kinds[kVoxelSolverCount];
    for (int i = 0; i < kVoxelSolverCount; ++i) {
        kinds[i] = voxelSolverLabel(static_cast<VoxelSolver>(i));
    }
    if (ImGui::Combo("solver (C)", &kind, kinds, kVoxelSolverCount)) {
        solver.kind = static_cast<VoxelSolver>(kind);
        *restart = touched = true;
    }
    if (solver.kind == VoxelSolver::PathTrace) {
        voxel::PathTraceOptions& path = solver.path;
        // The target only says where to stop: the samples so far stay.
        touched |= ImGui::SliderInt("target samples per pixel", &path.samplesPerPixel, 1, 65536,
                                    "%d", ImGuiSliderFlags_Logarithmic);
        path.samplesPerPixel = std::clamp(path.samplesPerPixel, 1, voxel::kMaxPathSamples);
        if (ImGui::SliderInt("max bounces", &path.maxBounces, 0, 16)) *restart = touched = true;
    } else if (solver.kind == VoxelSolver::SkyVisibility) {
        voxel::SkyVisibilityOptions& ao = solver.ao;
        if (ImGui::SliderInt("AO rays", &ao.rays, 1, 1024, "%d", ImGuiSliderFlags_Logarithmic)) {
            ao.rays = std::clamp(ao.rays, 1, voxel::kMaxSkyRays);
            *restart = touched = true;
        }
        bool wholeSky = std::isinf(ao.radius);
        if (ImGui::Checkbox("whole sky (AO radius infinite)", &wholeSky)) {
            ao.radius = wholeSky ? voxel::kInfinity : 16.0;
            *restart = touched = true;
        }
        if (!wholeSky) {
            float radius = static_cast<float>(ao.radius);
            if (ImGui::SliderFloat("AO radius", &radius, 0.5f, 1024.0f, "%.1f voxels",
                                   ImGuiSliderFlags_Logarithmic)) {
                ao.radius = std::clamp(static_cast<double>(radius), 0.5, 1024.0);
                *restart = touched = true;
            }
        }
    }
    if (solver.kind == VoxelSolver::Cascades) {
        ImGui::TextDisabled("one more reflection each frame until the light settles");
    }
    if (solver.kind != VoxelSolver::RayCast) {
        ImGui::TextDisabled("reflections, shading, shadows, surfaces: the ray caster's only");
    }
    return touched;
}

}  // namespace luxel::viewer
