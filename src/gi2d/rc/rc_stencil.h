// Stencil tracing of RC intervals through the pixel medium (docs/algorithms/radiance-cascades-2d.md
// §8). Every probe of a cascade sits on one grid, so for a direction k the interval of every probe
// is one segment moved by whole pixels: it crosses the same cells with the same lengths. The cells
// and lengths (the stencil) are found once per direction with the exact DDA; the probes then walk
// the stencil, many probes of a row at once (SIMD lanes), adding up optical depth cell by cell.
#pragma once

#include <cstdint>
#include <vector>

#include "gi2d/rc/rc_stencil_medium.h"
#include "luxel/core/vec.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::gi2d::rc {

// Cascade `i` as cascadePass(marcher, ...) computes it (gi2d/rc/rc_cascade_pass.h), to float
// rounding, with stencil walks. Stored values are slot-major here, in and out:
// (s * probesY + py) * probesX + px. Probes the stencils cannot serve (a bilinear-fix neighbour
// clamped at the grid's edge, a direction along a pixel edge) take the marcher.
std::vector<Rgb> cascadePassStencil(const RayMarcher& marcher, const StencilMedium& medium,
                                    const std::vector<RcCascade>& cascades, int i,
                                    const std::vector<Rgb>& upper, Rgb sky, RcMerge merge);

// Bytes cascadePassStencil holds for cascade i beyond its input and output.
std::uint64_t stencilPassBytes(int width, int height, const RcCascade& cascade, bool fix);

// ---- The SIMD walk (rc_stencil_walk.cpp, compiled for several instruction sets) ----

// Most lanes a walk uses. A plane row has this many vacuum cells between it and the next, so a
// group of lanes whose first lane lies left of the canvas (or last lane right of it) still loads
// inside the planes and reads vacuum there.
inline constexpr int kStencilLanes = 16;

// One group of lanes: `lanes` probes of a row, L = laneStride pixels apart, each walking the
// stencils of up to 4 corners (the bilinear fix's upper neighbours; 1 otherwise) and merging:
// sum[ch][l] += sum over corners c of weight[c] * (L_c + T_c * beyond[c][ch][l]).
struct StencilGroup {
    // Absorption per plane cell (cascadePassStencil lays the planes out): grey media one plane
    // (the three pointers equal), else one per channel; the first carries the sign bit where the
    // cell emits.
    const float* planes[3];
    bool grey;
    const StencilMedium* medium;
    // StencilMedium::uniformRadius laid out as the planes (0 off the canvas).
    const std::uint8_t* radius;
    int laneStride;
    int lanes;
    int corners;
    struct Walk {
        // Lane l's cell of entry j lies at plane index base + offset[j] + l, and is the pixel
        // (cellX[j] + shiftX + l * laneStride, cellY[j] + shiftY).
        std::int64_t base;
        const std::int32_t* offset;
        const float* length;  // of the segment inside entry j's cell
        const std::int32_t* cellX;
        const std::int32_t* cellY;
        int shiftX, shiftY;
        int begin, end;  // the entries walked
        // For crossing uniform squares (Stencil in rc_stencil_trace.h): cum[j] is the length of the
        // entries before j; firstX[r] is the first entry whose cell lies r columns from the
        // first cell's (relX(j) = (cellX[j] - cellX0) signX), up to spanX + 1; likewise y.
        const double* cum;
        const std::int32_t* firstX;
        const std::int32_t* firstY;
        int cellX0, cellY0, signX, signY, spanX, spanY;
    } walk[4];
    // Per corner and channel, lane l's value at [l] (kStencilLanes readable).
    const float* beyond[4][3];
    float weight[4];
    // Null, or per corner c and lane l at [c * kStencilLanes + l]: the corner whose walk serves
    // it (another where a neighbour is clamped at the grid's edge), or -1 for none.
    const std::int32_t* source;
    float* sum[3];  // kStencilLanes readable and writable
};

// A walk loads the cell of entry j + kStencilPrefetch into the cache while at entry j (the
// offsets array holds that many more entries).
inline constexpr int kStencilPrefetch = 32;

// Groups walked together, and their walks (groups times corners) at most: the walks take
// turns, so that the memory reads of one overlap the others'.
inline constexpr int kStencilBatch = 8;
inline constexpr int kStencilBatchWalks = 16;

// Lanes per group on this machine (at most kStencilLanes).
int stencilWalkLanes();
// Walks and merges `count` (1..kStencilBatch) groups of one pass, kStencilBatchWalks walks
// at most.
void walkStencilGroups(const StencilGroup* groups, int count);

}  // namespace luxel::gi2d::rc
