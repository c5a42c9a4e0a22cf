// The viewer's internal resolution when none is given: the largest that keeps frames under a
// target render time. Display-free (fed frame times and window sizes), so it is unit-tested.
#pragma once

#include <optional>

#include "luxel/core/image_size.h"

namespace luxel::viewer {

class AdaptiveResolution {
  public:
    // `start`: the first internal size (cheap everywhere); `targetMilliseconds`: render time per
    // frame to stay under (1000 / target fps).
    AdaptiveResolution(ImageSize start, double targetMilliseconds);

    // The largest useful size: the frame's rectangle in the window (more pixels than the window
    // shows make nothing sharper). Sizes keep this aspect ratio.
    void setLargest(ImageSize largest);

    // A frame rendered at `size` took `milliseconds` (at `seconds`, monotonic). Returns the size
    // to render at from now on when it should change. Render time is taken as proportional to
    // the pixel count; one fast frame is enough to grow (noise only slows frames down), two slow
    // frames in a row are needed to shrink (the first frame after a change pays for allocation).
    std::optional<ImageSize> frameRendered(ImageSize size, double milliseconds, double seconds);

    ImageSize current() const { return current_; }
    double targetMilliseconds() const { return targetMs_; }

    // Sides never go below this (pixels, the shorter side).
    static constexpr int kSmallestSide = 32;

  private:
    ImageSize sizeFor(double scale) const;
    double scaleOf(ImageSize size) const;

    ImageSize current_, largest_;
    double targetMs_;
    int slowFrames_ = 0;
    // A scale that proved too slow, and until when growth stays below it: a size that missed the
    // target is not retried at once (no oscillation), but is after a while (scene edits, solver
    // or backend switches change the cost).
    double ceilingScale_ = 0.0, ceilingUntil_ = 0.0;
};

}  // namespace luxel::viewer
