// Voxel mode's progressive path tracing: a voxel::PathTracer (or, on a GPU backend, a
// voxel::PathTracerGpu over the world the ray caster uploaded) whose samples are added a frame at
// a time while the view stays still, and thrown away when anything changes. The GPU tracer itself
// is kept for the next view (PathTracerGpu::restart: no world, emitters or sums sent again
// unless the world or its emitting materials changed). The path tracer's
// counter-based random numbers make the mean after N samples the same image `luxel render
// --solver path --spp N` computes, however the samples were split over frames.
#pragma once

#include <optional>

#include "luxel/core/error.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/path_trace_gpu.h"
#include "voxel_frame_source.h"

namespace luxel::viewer {

// Samples per pixel where the viewer's path tracer stops unless told otherwise (--spp).
inline constexpr int kDefaultViewerPathSamples = 1024;

// How long one frame's samples should take: below the adaptive resolution's 15 fps target, so
// the render thread hands the window a fresh mean about 20 times a second.
inline constexpr double kPathStepMilliseconds = 50.0;

// Samples for the next step: 1 right after a restart (the quickest first picture of a new view),
// then as many as the last step's time per sample fits into `budgetMilliseconds`, at most twice
// the last step's count (one quick step does not make the next one long), at least 1, and never
// past `target`. 0 when `done` has reached `target`.
int nextPathSamples(int done, int target, int lastCount, double lastMilliseconds,
                    double budgetMilliseconds);

class ProgressivePath {
  public:
    // Starts a new accumulation of this view, to stop at `target` samples per pixel
    // (1..kMaxPathSamples). `world` and `textures` must stay unchanged and alive until clear()
    // or the next restart. Fails when the options are invalid (validatePathTrace) or the
    // running sums do not fit in memory. With `gpu` (the world uploaded by a GPU source, which
    // must stay alive too, as long as this object or until a restart without it) the samples are
    // traced on its device, by the tracer of the last view when it read the same upload.
    Status restart(const voxel::VoxelWorld& world, const voxel::Camera& camera,
                   const voxel::ShadeOptions& shading, const voxel::PathTraceOptions& options,
                   const voxel::TextureSet* textures, int target, GpuWorld gpu = {});
    // Forgets the accumulation (the world or the view changed); a GPU tracer stays for reuse.
    void clear();
    // clear() and drops the GPU tracer too, with its sums and emitters on the device and the
    // host (another solver is shown: nothing of path mode stays allocated).
    void release();
    // Whether a GPU tracer (current or kept for reuse) is held.
    bool holdsGpuTracer() const { return gpuTracer_.has_value(); }
    // A new target for the same view: it keeps adding up to it, or stops where it is.
    void setTarget(int target);

    bool active() const { return tracer_.has_value() || gpuActive_; }
    bool onGpu() const { return gpuActive_; }
    bool finished() const { return !active() || samples() >= target_; }
    int samples() const {
        return tracer_ ? tracer_->samplesDone() : gpuActive_ ? gpuTracer_->samplesDone() : 0;
    }
    int target() const { return target_; }
    // Samples the last step added (0 when it only read the mean back).
    int lastAdded() const { return added_; }

    // Adds the next samples (nextPathSamples with `budgetMilliseconds`) and returns the mean so
    // far, with its standard error. Needs active().
    Result<voxel::PathTraceImage> step(double budgetMilliseconds);

  private:
    std::optional<voxel::PathTracer> tracer_;
    std::optional<voxel::PathTracerGpu> gpuTracer_;
    bool gpuActive_ = false;                       // gpuTracer_ holds the current view
    const voxel::VoxelWorld* gpuWorld_ = nullptr;  // the world gpuTracer_ was created for
    int target_ = 1;
    int lastCount_ = 0, added_ = 0;
    double lastMilliseconds_ = 0.0;
};

}  // namespace luxel::viewer
