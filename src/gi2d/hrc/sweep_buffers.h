// What the streaming HRC solver keeps while it sweeps a frustum from its far end to its near end
// (docs/algorithms/holographic-radiance-cascades.md §7.1): per cascade the two most recent planes
// of ray intervals and of merged cones (both binary16), one for the top cascade, and a window of
// medium columns for the traced cascades. Everything a plane needs lies at most one plane ahead,
// so two suffice; memory grows with the frame's rows times 2^levels, not with the rows times the
// planes of every cascade.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/near_lights.h"
#include "gi2d/hrc/sweep_kernels.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

// How many rows ahead the canvas is prefetched where the sweep walks a ±x frame's block of
// columns row by row: each row is another canvas row, a stride the hardware prefetcher does not
// follow (1024^2, one thread: the medium's load from 11.4% of the solve to 8.0%).
inline constexpr int kPrefetchRows = 8;

// Prefetches the cache lines of floats [from, from + count), for reading or (`write`) updating.
inline void prefetchFloats(const float* from, std::ptrdiff_t count, bool write) {
    constexpr std::ptrdiff_t kLineFloats = 16;
    for (std::ptrdiff_t f = 0; f < count + kLineFloats; f += kLineFloats) {
        if (write) {
            __builtin_prefetch(from + f, 1);
        } else {
            __builtin_prefetch(from + f);
        }
    }
}

// The frame's medium columns x .. x + span - 1 as cell transfers (sweep_kernels.h) for each ray
// length the traced cascades use, padded with vacuum rows above and below; columns beyond the
// frame read as vacuum.
class ColumnWindow {
  public:
    // Shapes the window for a frame (all vacuum); keeps the allocation when it is large enough.
    void reshape(int span, std::vector<float> lengths, int rows);

    // Frame columns are read from the canvas kColumnBlock at a time (a canvas row holds 16
    // neighbouring pixels of a ±x frame's columns: one cache line read instead of 16).
    static constexpr int kColumnBlock = 16;

    // Loads frame column x into its slot (rows [v0, v1) only: each team member loads its own
    // rows, and reads the canvas for the whole block of columns when x opens a block).
    void load(const Medium2D& medium, const FrustumFrame& frame, int x, int v0, int v1);
    // Columns x .. x + span - 1 into out[du * lengths + length index].
    void at(int x, CellTransfer* out) const;
    int span() const { return span_; }
    int lengths() const { return static_cast<int>(lengths_.size()); }

    // `bandRows`: the most rows one member loads (its band and the rows its stencils reach).
    static std::uint64_t bytesFor(int span, int lengths, int rows, int bandRows);
    // Bytes allocated now (the raw block once a column has been loaded).
    std::uint64_t bytes() const { return (data_.size() + block_.size()) * sizeof(float); }

  private:
    std::size_t offset(int slot, int length, int c) const {
        return ((static_cast<std::size_t>(slot) * lengths_.size() + length) * 6 + c) * stride_ +
               pad_;
    }
    int span_ = 1, rows_ = 0, pad_ = 0, stride_ = 0;
    std::vector<float> lengths_;
    std::vector<float> data_;
    // The raw sigma and E of the current block of columns for the rows this member loads:
    // [column][6][row - v0].
    std::vector<float> block_;
};

// Planes of cascade n of `levels` the sweep keeps when it handles `chunk` pixel columns per step:
// one more than the chunk holds (the plane ahead of it), at least 2; 1 for the top cascade, whose
// plane 1 is the only one the sweep computes (plane 0 of every cascade never reaches the image)
// (docs/algorithms/holographic-radiance-cascades.md §7.1, §8.1).
int ringSlots(int n, int levels, int chunk);

// The latest planes of intervals per cascade: plane p of cascade n lives in slot p mod slots(n).
class IntervalRing {
  public:
    // Shapes the ring for a frame; keeps the allocation when it is large enough.
    void reshape(int levels, int rows, int chunk);

    int rays(int n) const { return (1 << n) + 1; }
    IntervalRows read(int n, int p, int k, int offset = 0) const;
    IntervalRowsOut write(int n, int p, int k);

    static std::uint64_t bytesFor(int levels, int rows, int chunk);
    // Bytes allocated now.
    std::uint64_t bytes() const { return data_.size() * sizeof(std::uint16_t); }

  private:
    std::size_t index(int n, int p, int k) const {
        // Not a power of two in the lowest cascades (17 planes of cascade 0): a remainder, once
        // per row set, costs nothing next to the rows.
        const auto slot = static_cast<std::size_t>(p % slots_[n]);
        return levelStart_[n] + (slot * rays(n) + k) * 6 * rows_;
    }
    int rows_ = 0;
    std::vector<int> slots_;
    std::vector<std::size_t> levelStart_;
    std::vector<std::uint16_t> data_;
};

// The latest planes of merged cones per cascade: plane p of cascade n lives in slot
// p mod slots(n).
class ConeRing {
  public:
    // Shapes the ring for a frame; keeps the allocation when it is large enough.
    void reshape(int levels, int rows, int chunk);

    ConeRows read(int n, int p, int i, int offset = 0) const;
    std::uint16_t* plane(int n, int p, int i, int channel);

    static std::uint64_t bytesFor(int levels, int rows, int chunk);
    // Bytes allocated now.
    std::uint64_t bytes() const { return data_.size() * sizeof(std::uint16_t); }

  private:
    std::size_t index(int n, int p, int i) const {
        const auto slot = static_cast<std::size_t>(p % slots_[n]);
        return levelStart_[n] + (slot * (1u << n) + i) * 3 * rows_;
    }
    int rows_ = 0;
    std::vector<int> slots_;
    std::vector<std::size_t> levelStart_;
    std::vector<std::uint16_t> data_;
};

// The buffers of one sweep, reused by the frustums: the rings, and a column window per thread.
struct SweepBuffers {
    std::vector<ColumnWindow> columns;
    IntervalRing tables;
    ConeRing cones;
    NearLightMask nearLights;  // §12.3, told once per solve
};

}  // namespace luxel::gi2d::hrc
