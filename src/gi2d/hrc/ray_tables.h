// HRC ray tables T_n (docs/algorithms/holographic-radiance-cascades.md §3-4): for every cascade n,
// probe plane p, row y and ray k, the interval from (p 2^n, y + 0.5) to that point plus v_n(k).
// Stored as binary16 (12 bytes per entry), rows innermost: index = ((p * (2^n + 1) + k) * rows +
// y).
//
// Levels below `tracedLevels` are marched exactly through the medium; the rest are built by ray
// extension (paper Eq 18-20): T_n(k) averages the two bent paths
//   over(T_{n-1}(2p, y, lo), T_{n-1}(2p+1, y + dy(lo), hi)) and the same with lo and hi swapped,
// lo = k >> 1, hi = (k + 1) >> 1, which both end at v_n(k) since v_{n-1}(lo) + v_{n-1}(hi) =
// v_n(k).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "gi2d/hrc/interval.h"
#include "luxel/core/error.h"
#include "luxel/core/half.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d::hrc {

class RayTables {
  public:
    // Capacity for frames of up to `length` x `rows` (either orientation) and `levels` cascades.
    RayTables() = default;

    // Shapes the tables for a frame; keeps the allocation when it is large enough.
    void reset(int length, int rows, int levels);

    int levels() const { return levels_; }
    int rows() const { return rows_; }
    int planes(int n) const { return planes_[n]; }

    // Out of range (plane or row outside the frame) reads as empty space: L = 0, T = 1.
    Interval get(int n, int p, int y, int k) const {
        if (p < 0 || p >= planes_[n] || y < 0 || y >= rows_) return emptyInterval();
        return decode(tables_[n][index(n, p, k, y)]);
    }
    void set(int n, int p, int y, int k, const Interval& value) {
        tables_[n][index(n, p, k, y)] = encode(value);
    }

    // Decodes row (n, p, k) into `out` (rows x 6 floats: L rgb, T rgb); a plane outside the
    // frame decodes as empty space.
    void decodeRow(int n, int p, int k, std::vector<float>& out) const;
    // Encodes rows x 6 floats into row (n, p, k).
    void encodeRow(int n, int p, int k, const std::vector<float>& in);

    // The raw binary16 storage of level n (6 values per entry; layout in
    // src/gpu/shaders/shared/hrc_layout.h), for GPU uploads and readbacks.
    std::span<std::uint16_t> levelHalves(int n) {
        return {tables_[n][0].radiance, tables_[n].size() * 6};
    }
    std::span<const std::uint16_t> levelHalves(int n) const {
        return {tables_[n][0].radiance, tables_[n].size() * 6};
    }

    // Bytes for the tables of a frame (entries x 12 bytes).
    static std::uint64_t bytesFor(int length, int rows, int levels);

  private:
    // Six binary16 values: L rgb then T rgb.
    struct Entry {
        std::uint16_t radiance[3];
        std::uint16_t transmittance[3];
    };
    static Entry encode(const Interval& value) {
        Entry e;
        for (int c = 0; c < 3; ++c) {
            e.radiance[c] = floatToHalf(value.radiance[c]);
            e.transmittance[c] = floatToHalf(value.transmittance[c]);
        }
        return e;
    }
    static Interval decode(const Entry& entry) {
        Interval v;
        for (int c = 0; c < 3; ++c) {
            v.radiance[c] = halfToFloat(entry.radiance[c]);
            v.transmittance[c] = halfToFloat(entry.transmittance[c]);
        }
        return v;
    }

    std::size_t index(int n, int p, int k, int y) const {
        return (static_cast<std::size_t>(p) * ((1u << n) + 1) + k) * rows_ + y;
    }

    int levels_ = 0, rows_ = 0;
    std::vector<int> planes_;
    std::vector<std::vector<Entry>> tables_;
};

// A decoded table row with out-of-range rows reading as empty space.
struct DecodedRow {
    std::vector<float> values;  // rows x 6
    int rows = 0;

    Interval at(int y) const {
        if (y < 0 || y >= rows) return emptyInterval();
        const float* e = &values[static_cast<std::size_t>(y) * 6];
        return {{e[0], e[1], e[2]}, {e[3], e[4], e[5]}};
    }
    void load(const RayTables& tables, int n, int p, int k) {
        rows = tables.rows();
        tables.decodeRow(n, p, k, values);
    }
};

// Marches T_n with the exact DDA (exact optical depth on diagonals), the optical depth times
// `depthScale` (hrcTracedDepthScale, §3.1): the CPU twin of hrc_trace.
void traceLevel(RayTables& tables, const RayMarcher& marcher, int n, float depthScale = 1.0f);
// traceLevel for every n < tracedLevels, each with its hrcTracedDepthScale.
void traceBaseLevels(RayTables& tables, const RayMarcher& marcher, int tracedLevels);

// Builds T_n (n >= 1) from T_{n-1} by extension (paper Eq 18-20): the CPU twin of hrc_extend.
void extendLevel(RayTables& tables, int n);
// extendLevel for every tracedLevels <= n < levels.
void extendLevels(RayTables& tables, int tracedLevels);

}  // namespace luxel::gi2d::hrc
