// The CPU HRC solver as one sweep per frustum from the far end of the frame to the near end
// (docs/algorithms/holographic-radiance-cascades.md §7.1): chunk by chunk of pixel columns, the
// planes of every cascade that lie in the chunk are traced or extended bottom-up, then merged
// top-down and read out, so each cascade holds only the chunk's planes and the one beyond. The
// same arithmetic as the level-by-level passes (ray_tables, cone_merge, readout), which stay as
// the reference of the GPU passes.
#pragma once

#include <cstdint>

#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/light_scores.h"
#include "luxel/core/image.h"
#include "luxel/core/thread_team.h"
#include "luxel/gi2d/hrc_solver.h"

namespace luxel::gi2d::hrc {

// Wall time and the bytes of tables, cones and medium each pass reads and writes (member 0's
// clock: barrier waits count towards the pass that waited).
struct SweepTimes {
    enum Pass { Trace, Extend, Merge, Readout, Count };
    double milliseconds[Count] = {};
    std::uint64_t bytes[Count] = {};
};

// Pixel columns the sweep handles per step (§7.1).
inline constexpr int kSweepChunk = 16;

// The most traced cascades the sweep takes; more are solved cascade by cascade.
inline constexpr int kSweepMaxTracedLevels = 5;

// Adds the angular fluence each pixel's read-out plane receives in every frustum of `mask` into
// `beyondSum` (canvas space), using `threads` threads. `scores` (the medium's) make the near-light
// mask and are freed before the rings are allocated.
void sweepFrustums(const Medium2D& medium, LightScores scores, const HrcOptions& options,
                   int threads, Image& beyondSum, SweepTimes* times);

// Bytes of sweepFrustums' buffers for a canvas of this size on `threads` threads: each the larger
// of the ±x and ±y frames', since the buffers keep their allocations from frame to frame.
struct SweepMemory {
    std::uint64_t intervals = 0;   // the ring of ray intervals
    std::uint64_t cones = 0;       // the ring of merged cones
    std::uint64_t columns = 0;     // per thread: the medium window and the read-out's block
    std::uint64_t nearLights = 0;  // the near-light mask, a byte per pixel (§12.3)
    std::uint64_t total() const { return intervals + cones + columns + nearLights; }
};
SweepMemory sweepMemory(int width, int height, int tracedLevels, int threads);

}  // namespace luxel::gi2d::hrc
