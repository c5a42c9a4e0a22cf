// Holographic Radiance Cascades (Freeman, Sannikov, Margel 2025, arXiv:2505.02041): per-pixel 2D
// fluence in O(N^2 log N), in the same normalisation as the reference solver (mean radiance over
// directions), so the two compare pixel for pixel. Design notes:
// docs/algorithms/holographic-radiance-cascades.md.
#pragma once

#include <cstdint>
#include <functional>
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
    // Which frustums to sum (bit r: 0 = +x, 1 = +y, 2 = -x, 3 = -y); debug views use one.
    unsigned frustumMask = 0xF;
    // >= 0: instead of the fluence, show cascade n's merged result read at each pixel's next
    // plane (all cones summed). Debug view; cascades above n are merged as usual.
    int debugCascade = -1;
    // Called from the calling thread after each frustum pass with (done, total) steps.
    std::function<void(int done, int total)> onProgress;
};

struct HrcMemory {
    std::uint64_t rayTables = 0;    // T_0 .. T_{N_c - 1}, binary16, reused by the 4 frustums
    std::uint64_t coneBuffers = 0;  // two R ping-pong buffers, float RGB
    std::uint64_t frame = 0;        // the rotated medium and its ray marcher
    std::uint64_t output = 0;       // fluence accumulator
    std::uint64_t total() const { return rayTables + coneBuffers + frame + output; }
};

// Memory solveHrc needs for a canvas of this size (the input medium not counted).
HrcMemory estimateHrcMemory(int width, int height);

// Number of cascades used for a canvas of this size.
int hrcCascadeCount(int width, int height);

// Fails with a clear message when the memory estimate exceeds the available memory, or for bad
// options.
Result<Image> solveHrc(const Medium2D& medium, const HrcOptions& options = {});

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
