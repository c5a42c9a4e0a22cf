// The statistics overlay: FPS, render time, per-pass timings (GPU timestamps on the GPU backend),
// resolution, backend and device, drawn with Dear ImGui above the mode's own controls.
#pragma once

#include <string>

#include "frame.h"
#include "viewer_mode.h"

namespace luxel::viewer {

// Smoothed rates for the overlay.
class RateMeter {
  public:
    // Records one event at `seconds` (monotonic).
    void tick(double seconds);
    // Events per second: over the last half second, or since the first event until half a
    // second has passed; 0 before the second event (unknown).
    double perSecond() const { return rate_; }

  private:
    double windowStart_ = -1.0, rate_ = 0.0;
    int count_ = 0;
    bool windowsDone_ = false;
};

struct OverlayInfo {
    const Frame* frame = nullptr;  // may be null before the first frame
    double windowFps = 0.0;
    double renderFps = 0.0;
    int windowWidth = 0, windowHeight = 0;
    std::string lastScreenshot;
    double adaptiveTargetFps = 0.0;  // > 0: the internal size adapts to this frame rate
};

// Draws the "luxel-view" window: statistics, then the mode's panel.
void drawOverlay(const OverlayInfo& info, ViewerMode& mode);

}  // namespace luxel::viewer
