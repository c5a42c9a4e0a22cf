// The voxel frame producer on the render thread: owns the world, applies edits (so the ray
// caster never reads a world being changed), renders through a VoxelFrameSource and tone maps.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frame.h"
#include "luxel/core/tonemap.h"
#include "luxel/post/post_options.h"
#include "luxel/post/temporal.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/radiance_cascades_gpu.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/sky_visibility.h"
#include "luxel/voxel/voxel_world.h"
#include "progressive_path.h"
#include "voxel_frame_source.h"
#include "voxel_solver.h"

namespace luxel::viewer {

// A click: remove the first voxel along the ray, or add one on the face it hits.
struct VoxelEdit {
    voxel::Ray ray;
    bool add = false;
    voxel::Voxel colour{200, 200, 200, 255};
};

struct FlyCamera {
    Vec3d position;
    double yawDegrees = 0, pitchDegrees = 0, fovYDegrees = 60;
};

// The solver and the settings of the two that are not the ray caster (whose are `shading`).
struct VoxelSolverOptions {
    VoxelSolver kind = VoxelSolver::RayCast;
    // samplesPerPixel: where the accumulation stops (the mean is then `luxel render --solver
    // path --spp N` of the view).
    voxel::PathTraceOptions path{.samplesPerPixel = kDefaultViewerPathSamples};
    voxel::SkyVisibilityOptions ao;
};

struct VoxelState {
    FlyCamera camera;
    int width = 320, height = 180;  // frame resolution (rendered at post.internalScale of it)
    voxel::ShadeOptions shading;
    float exposure = 0.0f;
    // Bloom, tone curve, internal scale and upscaler (post.tone's exposure is `exposure`).
    post::PostOptions post;
    // Temporal upscaling: jittered frames at the internal scale, reprojected history.
    bool temporal = false;
    VoxelSolverOptions solver;
    std::vector<VoxelEdit> edits;  // new since the previous state
    // False when this state differs from the previous one only in what the finished picture
    // shows of the same light (exposure, the path tracer's target): the path tracer keeps its
    // samples and sky visibility its image.
    bool restart = true;
};

// Applies one edit; returns whether a voxel changed, and the changed voxel in `changed`.
bool applyVoxelEdit(voxel::VoxelWorld& world, const VoxelEdit& edit, Int3* changed = nullptr);

class RendererVoxel {
  public:
    using State = VoxelState;
    RendererVoxel(voxel::VoxelWorld world, std::unique_ptr<VoxelFrameSource> source);

    void setState(VoxelState&& state);
    // Also while the temporal upscaler is still converging on a still view, and while the path
    // tracer has not reached its target.
    bool hasMoreWork() const;
    Frame step();

  private:
    // Linear radiance of the view at the internal camera by sky visibility, the path tracer or
    // the radiance cascades; fills in the frame's samples, convergence, metadata and passes.
    Result<Image> renderLight(const voxel::Camera& internal, Frame& frame);
    // The radiance cascades' frame: built once per world, new light when the sun or sky change,
    // one lighting pass (one more reflection) per frame until the light settles.
    Result<Image> renderCascades(const voxel::Camera& internal, Frame& frame);

    voxel::VoxelWorld world_;
    std::unique_ptr<VoxelFrameSource> source_;
    VoxelState state_;
    bool dirty_ = false;
    std::optional<post::TemporalUpscaler> temporal_;
    ProgressivePath path_;
    std::optional<Image> skyVisibility_;  // the last sky visibility render, until a restart
    std::optional<voxel::RadianceCascades> cascades_;  // of world_, until an edit
    bool cascadesLight_ = false;                       // the state's light is not yet set in them
    double cascadesChange_ = 1.0;                      // the last pass's relative change
    // The cascades' pass and picture on a GPU source's device (declared after cascades_, which
    // it reads, so it goes first), and why the device could not take them.
    std::optional<voxel::RadianceCascadesGpu> cascadesGpu_;
    std::string cascadesGpuRefusal_;
};

}  // namespace luxel::viewer
