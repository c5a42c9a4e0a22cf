// The reference solver as a progressive accumulation: each pass integrates every pixel over a few
// stratified directions with a new seed, and the picture is the running mean, so the viewer shows
// a noisy image at once and a converged one later without ever blocking on a long solve.
#pragma once

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::viewer {

class ProgressiveReference {
  public:
    explicit ProgressiveReference(int raysPerPass = 4) : raysPerPass_(raysPerPass) {}

    void reset();
    // Adds one pass (seed = pass number, so a run is reproducible).
    Status addPass(const gi2d::Medium2D& medium);
    // Mean fluence so far (empty before the first pass).
    Image mean() const;
    int passes() const { return passes_; }
    int raysPerPixel() const { return passes_ * raysPerPass_; }

  private:
    int raysPerPass_;
    int passes_ = 0;
    Image sum_;
};

}  // namespace luxel::viewer
