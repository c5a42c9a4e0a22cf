// Temporal upscaling with reprojection (in the spirit of TAAU / FSR 2, written from their
// published descriptions): each frame renders at the internal resolution through a sub-pixel
// jittered camera; a history at the output resolution is reprojected to the current camera with
// per-pixel depth, clamped to the current frame's neighbourhood (against ghosting) and blended
// with the new samples by their distance to each output pixel (exponential blend, at least
// 1 / maxWeight per frame). docs/algorithms/post-processing.md.
#pragma once

#include "luxel/core/image.h"
#include "luxel/core/vec.h"
#include "luxel/post/pinhole_view.h"

namespace luxel::post {

struct TemporalSettings {
    float maxWeight = 16.0f;   // history weight cap: the slowest blend is 1 / maxWeight
    float sampleSigma = 0.5f;  // Gaussian radius of a sample's reach, in output pixels
};

class TemporalUpscaler {
  public:
    TemporalUpscaler(int outputWidth, int outputHeight, TemporalSettings settings = {});

    // The sub-pixel offset of frame `index`, in internal pixels in [-0.5, 0.5): Halton (2, 3).
    static Vec2d jitter(int index);
    // The jitter the next accumulate() expects.
    Vec2d nextJitter() const { return jitter(frame_); }

    // Adds a frame rendered at the internal size with rays through (x + 0.5 + jitter.x,
    // y + 0.5 + jitter.y). `depth` (same size, 1 channel): distance along each unit ray, +inf for
    // the sky. `view`: the camera at the output size (position and orientation of this frame).
    // Returns the output image.
    const Image& accumulate(const Image& colour, const Image& depth, const PinholeView& view,
                            Vec2d frameJitter);

    // Forgets the history (a cut, a scene edit).
    void reset();
    const Image& output() const { return output_; }
    int frames() const { return frame_; }

  private:
    int width_, height_;
    TemporalSettings settings_;
    int frame_ = 0;
    bool hasHistory_ = false;
    PinholeView previous_;
    Image output_, weight_, history_, historyWeight_;
};

}  // namespace luxel::post
