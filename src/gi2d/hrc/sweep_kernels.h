// The row loops of the streaming HRC solver (docs/algorithms/holographic-radiance-cascades.md
// §7.1), vectorised across the rows of a frame with Highway and dispatched at run time to the best
// SIMD target of the CPU. Every row is computed by the same vector instructions whatever range it
// is called with, so results do not depend on how rows are split between threads.
//
// Rows are planes of `rows` consecutive values, one plane per channel. Every plane a kernel reads
// must stay readable for kSweepRowPad values past its last row (whole vectors are loaded; the
// lanes beyond the range are never stored).
#pragma once

#include <cstdint>
#include <span>

#include "gi2d/hrc/trace_stencil.h"

namespace luxel::gi2d::hrc {

inline constexpr int kSweepRowPad = 64;

// An interval row: six binary16 planes (L r, g, b, then T r, g, b) read at row y + offset;
// `plane[0] == nullptr` reads as empty space (L = 0, T = 1).
struct IntervalRows {
    const std::uint16_t* plane[6] = {};
    int offset = 0;
};
struct IntervalRowsOut {
    std::uint16_t* plane[6] = {};
};

// A cone-fluence row: three binary16 planes read at row y + offset; `plane[0] == nullptr` reads as
// the constant `fill` (the sky beyond the frame, times the cone's width).
struct ConeRows {
    const std::uint16_t* plane[3] = {};
    float fill[3] = {};
    int offset = 0;
};

// One medium column of the frame seen by rays of one length through its cells: per row the
// transmittance t = exp(-sigma length) and the radiance E (1 - t) a cell gives that ray, planes
// t r, g, b then L r, g, b (rows just outside the frame read as vacuum: t = 1, L = 0).
struct CellTransfer {
    const float* plane[6] = {};
};

// A stencil step with its column and length resolved: transfer columns[column] at row y + dv.
struct TraceStep {
    int column = 0;
    int dv = 0;
};

// Rows [y0, y1) of a traced ray: the cells of `steps` composited front to back (paper Eq 8).
void traceRows(std::span<const TraceStep> steps, const CellTransfer* columns, IntervalRowsOut out,
               int y0, int y1);

// t = exp(-sigma length) (exactly 1 where sigma = 0) and L = E (1 - t) for `count` cells: the
// per-cell part of tracing, done once per cell and ray length.
void cellTransferRows(const float* const sigma[3], const float* const emission[3], float length,
                      float* const t[3], float* const l[3], int count);

// to[3 i + c] += from[c][i] for i in [0, count), c < 3: planes added to RGB pixels.
void addRgbPlanes(float* to, const float* const from[3], int count);

// to[r toStride + k] += from[r fromStride + index[k]] for k < floats, r < rows: a block of
// planes added across canvas rows (each row's floats gathered from the planes), with the
// canvas rows `prefetchRows` ahead fetched by hand (strides the prefetcher does not follow).
void addGatheredRows(float* to, std::ptrdiff_t toStride, const float* from, int fromStride,
                     const std::int32_t* index, int floats, int rows, int prefetchRows);

// Rows [y0, y1) of an extended ray (paper Eq 18-20): over(nearA, farA), averaged with
// over(nearB, farB) when `twoPaths`.
void extendRows(const IntervalRows& nearA, const IntervalRows& farA, const IntervalRows& nearB,
                const IntervalRows& farB, bool twoPaths, IntervalRowsOut out, int y0, int y1);

// One side (ray) of a cone merge (§5, §5.1). Upper cones are blends of neighbouring rows
// (hrcBlendTwoRows, hrcBlendThreeRows in shared/hrc_kernels.h).
struct MergeSide {
    IntervalRows here;  // T_n(p, k) at row y
    IntervalRows next;  // even planes: T_n(p + 1, k) at row y + dy
    // Odd planes: the ray's end probe and the row towards the bisector; even: the near probe and
    // the row along the ray (§5.1).
    ConeRows upperA, upperA2;
    // Even planes: the far probe, reached by the double-length ray, and the rows one and two
    // towards the bisector.
    ConeRows upperB, upperB2, upperB3;
    float weight = 0.0f;  // the upper cone's angular width
};

// Rows [y0, y1) of R_n(p, i): the sum over the cone's two rays of Eq 14 (odd planes) or Eq 15-17
// (even planes), summed in float and written to out[c][y] as binary16.
// `second` weighs the rows towards the bisector, `nearSecond` the near probe's second row
// (hrcSecondRowWeight, hrcNearRowWeight), or `nearRows[y]` per row where given (cascade 0 near a
// light, hrcNearRowWeightAt; readable for kSweepRowPad values past y1).
void mergeRows(bool odd, const MergeSide& side0, const MergeSide& side1, float second,
               float nearSecond, const float* nearRows, std::uint16_t* const out[3], int y0,
               int y1);

}  // namespace luxel::gi2d::hrc
