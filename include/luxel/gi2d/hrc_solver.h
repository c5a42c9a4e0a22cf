// Holographic Radiance Cascades (Freeman, Sannikov, Margel 2025, arXiv:2505.02041): per-pixel 2D
// fluence in O(N^2 log N), in the same normalisation as the reference solver (mean radiance over
// directions), so the two compare pixel for pixel. Design notes:
// docs/algorithms/holographic-radiance-cascades.md.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gpu/fwd.h"

namespace luxel::gi2d {

struct HrcOptions {
    // Cascades whose rays are marched exactly; the rest are built by ray extension. The paper
    // traces 3; 1 is the GameMaker HRC demo's "extend from c0" variant (here with exact optical
    // depth).
    int tracedLevels = 3;
    // Opacity-gated cross blur against the row-parity checkerboard (paper Eq 21).
    bool crossBlur = true;
    // Where every pixel absorbs enough that a ray fades below 1e-3 within 512 px, replace the
    // fluence within 5 px of the lights, where HRC's bias sits, by 128 directions marched exactly
    // (docs/algorithms/holographic-radiance-cascades.md §12.3, "An exact near field in fog"),
    // unless those rays would cost more than a budget. Elsewhere (any vacuum or thin medium) it
    // does nothing; off for the debug views and for fewer than four frustums.
    bool exactNearField = true;
    // The compact lights' direct light added exactly, their emission taken out of the medium the
    // cascades solve (docs/algorithms/holographic-radiance-cascades.md §12.5), within a budget of
    // marched pixels; off for the debug views and for fewer than four frustums.
    bool exactDirectLight = true;
    // Which frustums to sum (bit r: 0 = +x, 1 = +y, 2 = -x, 3 = -y); debug views use one.
    unsigned frustumMask = 0xF;
    // >= 0: instead of the fluence, show cascade n's merged result read at each pixel's next
    // plane (all cones summed). Debug view; cascades above n are merged as usual.
    int debugCascade = -1;
    // Called from the calling thread after each frustum pass with (done, total) steps.
    std::function<void(int done, int total)> onProgress;
};

// The CPU solver sweeps each frustum from its far end and keeps two planes per cascade, one of
// the top cascade (docs/algorithms/holographic-radiance-cascades.md §7.1).
struct HrcMemory {
    std::uint64_t rayIntervals = 0;   // two planes of intervals per cascade, binary16
    std::uint64_t cones = 0;          // two planes of merged cones per cascade, binary16
    std::uint64_t mediumColumns = 0;  // per thread: the medium columns and the read-out's block
    std::uint64_t nearLights = 0;     // where the lights are, a byte per pixel (§12.3)
    std::uint64_t output = 0;         // the fluence, accumulated and finished in place
    std::uint64_t total() const {
        return rayIntervals + cones + mediumColumns + nearLights + output;
    }
};

// Memory solveHrc needs for a canvas of this size (the input medium not counted).
HrcMemory estimateHrcMemory(int width, int height);

// Number of cascades used for a canvas of this size.
int hrcCascadeCount(int width, int height);

// One pass of the CPU solver: wall milliseconds on the calling thread (waits for the other
// threads included, so the passes add up to the solve) and the bytes of ray intervals, cones and
// medium it reads and writes.
struct HrcCpuPass {
    std::string name;
    double milliseconds = 0;
    std::uint64_t bytes = 0;
};

// Fails with a clear message when the memory estimate exceeds the available memory, or for bad
// options. `passes`, when given, receives the time of each pass (trace, extend, merge, readout,
// finish, and "near field" where the exact near field acted) summed over the frustums; it stays
// empty for the debug views and for more than 5 traced cascades, which run cascade by cascade.
Result<Image> solveHrc(const Medium2D& medium, const HrcOptions& options = {},
                       std::vector<HrcCpuPass>* passes = nullptr);

// The same on the GPU (Vulkan compute): the medium is rotated on the CPU and uploaded per frustum;
// trace, extend, merge, read-out and finish run as named dispatches whose GPU times are appended
// to `timings` (with "upload" entries for the CPU-side copies, timed on the CPU). The debug
// cascade view is CPU-only. Device memory is checked before allocating.
Result<Image> solveHrcOnGpu(gpu::Context& context, const Medium2D& medium,
                            const HrcOptions& options = {},
                            std::vector<gpu::PassTiming>* timings = nullptr);

// Device memory solveHrcOnGpu needs.
std::uint64_t estimateHrcGpuMemory(int width, int height);

}  // namespace luxel::gi2d
