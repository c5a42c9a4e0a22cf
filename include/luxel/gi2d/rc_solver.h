// Vanilla 2D Radiance Cascades (Sannikov, "Radiance Cascades", WIP paper; the raylib
// radiance-cascades demo's version; design notes docs/algorithms/radiance-cascades-2d.md) with the
// bilinear fix (Osborne & Sannikov 2024, arXiv:2408.14425). Same fluence convention as the
// reference solver.
#pragma once

#include <cstdint>
#include <functional>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/sdf_scene.h"
#include "luxel/gpu/fwd.h"

namespace luxel::gi2d {

enum class RcMerge {
    Vanilla,      // each ray merges the bilinear blend of 4 upper probes' (pre-averaged) children
    BilinearFix,  // each ray is traced to each of the 4 upper probes' interval starts (4x rays)
};

struct RcOptions {
    int probeSpacing = 1;       // cascade-0 probe spacing in pixels (x2 per cascade)
    int baseRays = 4;           // cascade-0 directions per probe (x4 per cascade)
    double baseInterval = 1.0;  // cascade-0 interval length in pixels (x4 per cascade)
    int maxCascades = 0;        // cap on the cascade count; 0 = ceil(log4(diag / base)) + 1
    // The fix by default: vanilla leaks, rings and pops more (docs/solver-errors.md).
    RcMerge merge = RcMerge::BilinearFix;
    // >= 0: show cascade n's merged radiance averaged over its directions (nearest probe) instead
    // of the fluence. Debug view.
    int debugCascade = -1;
    // Probe-grid jitter (docs/algorithms/radiance-cascades-2d.md §7): the probe grid of every
    // cascade above 0 shifted by this fraction of its spacing, each in [0, 1). The viewer takes a
    // new shift each frame and averages frames.
    double jitterX = 0, jitterY = 0;
    // Solves averaged, each with its own shift (a 2D low-discrepancy sequence; 1: one solve with
    // jitterX/Y). A light no longer pops in blocks of one fixed grid's probe spacing as it moves.
    int jitters = 1;
};

// Shift r (r >= 0) of the jittered probe grids (RcOptions::jitterX/Y): the R2 low-discrepancy
// sequence, which spreads any number of shifts evenly over the unit square. solveRc with
// `jitters` = N averages shifts 0..N-1; the viewer adds one per frame.
void rcJitterShift(int r, double& x, double& y);

// Cascade geometry for a canvas (the raylib demo's formulas): cascade i has probes every spacing *
// 2^i px, baseRays * 4^i directions at angles 2 pi (k + 0.5) / rays, and covers distances [base
// (4^i - 1) / 3, base (4^i - 1) / 3 + base 4^i).
struct RcCascade {
    double spacing;
    int probesX, probesY;
    int rays;
    double intervalStart, intervalEnd;
    // Probe (px, py) sits at ((px + 0.5) spacing + offsetX, (py + 0.5) spacing + offsetY).
    double offsetX = 0, offsetY = 0;
};
std::vector<RcCascade> rcCascades(int width, int height, const RcOptions& options);

// Bytes solveRc needs (two cascade buffers, pre-averaged, float RGB; the stencil walks' copy of
// the medium; plus the output).
std::uint64_t estimateRcMemory(int width, int height, const RcOptions& options);

// Traces intervals through the pixel medium with the exact DDA (works for every medium).
Result<Image> solveRc(const Medium2D& medium, const RcOptions& options = {});
// Traces intervals with sphere tracing.
Result<Image> solveRc(const SdfScene& scene, Rgb boundaryRadiance, const RcOptions& options = {});

// The DDA variant on the GPU: one dispatch per cascade (shader rc_cascade), top-down, GPU times
// appended to `timings`; the medium is uploaded once. Same result as solveRc(medium, options).
Result<Image> solveRcOnGpu(gpu::Context& context, const Medium2D& medium,
                           const RcOptions& options = {},
                           std::vector<gpu::PassTiming>* timings = nullptr);

}  // namespace luxel::gi2d
