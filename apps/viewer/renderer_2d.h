// The 2D frame producer that runs on the render thread: rasterises the scene at the internal
// size, runs the chosen solver on the CPU or the GPU (Vulkan), tone maps and marks probes. It
// caches the medium and the fluence so display-only changes (exposure, probes) are instant.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "frame.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/scene2d.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/fwd.h"
#include "progressive_reference.h"

namespace luxel::viewer {

struct View2D {
    gi2d::Solver2D solver = gi2d::Solver2D::Hrc;
    gi2d::RcMerge merge = gi2d::RcMerge::BilinearFix;  // RC only
    gpu::Backend backend = gpu::Backend::Auto;
    std::string device;     // Vulkan device choice (ContextOptions::device)
    bool gi = true;         // false: emission only (the raylib demo's R)
    bool probes = false;    // mark probe centres (the raylib demo's SPACE)
    int cascade = -1;       // >= 0: show that cascade instead of the fluence (the raylib demo's C)
    float exposure = 0.0f;  // stops
    // Bounce light (HRC, RC; scenes with albedo): one bounce per frame, the previous frame's
    // fluence fed back through gi2d::bounceSource, up to `bounces` frames after each change.
    bool bounce = true;
    int bounces = 16;
    // RC: after each change, this many frames each add one solve with the probe grids above
    // cascade 0 shifted differently (gi2d::rcJitterShift) to a running mean; 1 = one fixed grid.
    // Not while bounce light is being fed back.
    int rcJitters = 16;
    // HRC's exact corrections (docs/algorithms/holographic-radiance-cascades.md §12.3, §12.5):
    // the near field in fog and the compact lights' direct light. Accurate, but the direct light
    // can cost several solves' time on the CPU where lights are many or large, so the panel can
    // turn them off.
    bool exactNearField = true;
    bool exactDirectLight = true;
    int width = 256, height = 256;  // internal resolution
};

struct State2D {
    std::shared_ptr<const gi2d::Scene2D> scene;
    std::uint64_t sceneVersion = 0;  // grows with every edit, so the medium is rebuilt only then
    View2D view;
};

// Cascades the C key cycles through for this view's solver and size (0 for the reference solver).
int cascadeCount(const View2D& view);

class Renderer2D {
  public:
    using State = State2D;
    Renderer2D();
    ~Renderer2D();

    void setState(State2D&& state);
    bool hasMoreWork() const;
    Frame step();

  private:
    // Whether to use the GPU for this view; creates the context on first use. Sets `note_`.
    gpu::Context* gpuFor(const View2D& view);
    Status solve(Frame& frame);
    // Whether this view feeds fluence back, and whether a bounce is still to come.
    bool bouncing() const;
    // Whether RC frames add jittered probe grids to a running mean (View2D::rcJitters).
    bool jitteringRc() const;

    State2D state_;
    bool mediumDirty_ = true, fluenceDirty_ = true, displayDirty_ = true;
    gi2d::Medium2D medium_;
    Image fluence_;
    gi2d::Medium2D lit_;   // medium_ with the bounced source as its emission (when bouncing)
    int bouncesDone_ = 0;  // frames that fed fluence back since the last change
    Image rcSum_;          // sum of the jittered RC solves since the last change
    int rcJittersDone_ = 0;
    ProgressiveReference reference_;
    int referenceTargetPasses_ = 256;  // 1024 rays per pixel, the reference solver's default
    std::unique_ptr<gpu::Context> gpu_;
    std::string gpuError_;  // why there is no context ("" = not tried or fine)
    bool gpuTried_ = false;
    std::string note_;
    Frame last_;  // the previous frame's report, reused when only the display changes
};

}  // namespace luxel::viewer
