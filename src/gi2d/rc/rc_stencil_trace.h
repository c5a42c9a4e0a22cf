// The pieces of the CPU RC pass's stencil tracing (docs/algorithms/radiance-cascades-2d.md §8):
// the medium in lane-strided planes, and the stencil of one direction (the cells a segment
// crosses, with the tables a walk uses to cross uniform squares).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "gi2d/rc/rc_stencil.h"
#include "gi2d/rc/rc_stencil_medium.h"
#include "luxel/core/parallel.h"
#include "luxel/core/vec.h"

namespace luxel::gi2d::rc {

inline int floorDiv(int a, int b) {
    return a / b - ((a % b != 0 && (a < 0) != (b < 0)) ? 1 : 0);
}

// The medium's absorption split by the phase of x modulo the lane stride L: row y, phase p,
// column m holds pixel (m L + p, y); each such row of columns is followed by kStencilLanes vacuum
// cells, and the L phase rows of a pixel row lie together (a ray along x stays near in memory).
// Lanes l of a group (probes L pixels apart) thus read consecutive floats, and a group reaching
// past either end of a row reads vacuum. Grey media need one plane set, others three; the first
// carries the sign bit where the cell emits.
struct Planes {
    int stride = 1, rowLen = 0, rowStride = 0;
    std::int64_t planeSize = 0;  // between pixel rows
    int channels = 1;
    std::vector<float> data[3];
    std::vector<std::uint8_t> radius;  // StencilMedium::uniformRadius, 0 off the canvas

    static std::int64_t cells(int width, int height, int stride) {
        const std::int64_t rowLen = (width + stride - 1) / stride;
        return static_cast<std::int64_t>(stride) * height * (rowLen + kStencilLanes) +
               2 * kStencilLanes;
    }

    Planes(const StencilMedium& medium, int laneStride) : stride(laneStride) {
        const int w = medium.width(), h = medium.height();
        rowLen = (w + stride - 1) / stride;
        rowStride = rowLen + kStencilLanes;
        planeSize = static_cast<std::int64_t>(stride) * rowStride;
        channels = medium.grey() ? 1 : 3;
        for (int c = 0; c < channels; ++c) {
            data[c].assign(static_cast<std::size_t>(cells(w, h, stride)), 0.0f);
        }
        radius.assign(static_cast<std::size_t>(cells(w, h, stride)), 0);
        parallelForRange(stride * h, 16, [&](int begin, int end) {
            for (int row = begin; row < end; ++row) {
                const int phase = row / h, y = row % h;
                const std::int64_t first = index(phase, y);
                const std::uint8_t* r = medium.uniformRadius() + static_cast<std::size_t>(y) * w;
                for (int m = 0, x = phase; x < w; ++m, x += stride) radius[first + m] = r[x];
                for (int c = 0; c < channels; ++c) {
                    const float* in = medium.planeSigma(c) + static_cast<std::size_t>(y) * w;
                    float* out = data[c].data() + first;
                    if (stride == 1) {
                        std::copy_n(in, w, out);
                        continue;
                    }
                    for (int m = 0, x = phase; x < w; ++m, x += stride) out[m] = in[x];
                }
            }
        });
    }

    // Plane index of pixel (x, y).
    std::int64_t index(int x, int y) const {
        const int m = floorDiv(x, stride);
        return kStencilLanes + static_cast<std::int64_t>(y) * planeSize +
               (x - m * stride) * rowStride + m;
    }
};

// The cells a segment crosses, in order, with the length inside each: the exact DDA of
// RayMarcher (unit cells, no runs or blocks), so that the lengths add up to its run lengths.
struct Stencil {
    std::vector<std::int32_t> cellX, cellY, column, offset;
    std::vector<float> length;
    // cum[j]: the lengths of entries before j (summed exactly: doubles of floats); firstX[r]:
    // the first entry r or more columns from the first cell (in the direction of travel), the
    // entry count past the last; firstY likewise for rows.
    std::vector<double> cum;
    std::vector<std::int32_t> firstX, firstY;
    int signX = 1, signY = 1;
    int minY = 0, maxY = 0, minColumn = 0, maxColumn = 0;
    // Along a pixel edge the cells of two probes can differ by a rounding: not served.
    bool degenerate = false;

    // The segment [from, to] clipped to the box [lo, hi) of cells that can matter (integral
    // bounds), with each cell's plane column and index.
    void trace(Vec2d from, Vec2d to, Vec2d lo, Vec2d hi, const Planes& planes) {
        resize(0);
        const Vec2d delta = to - from;
        const double len = std::sqrt(delta.x * delta.x + delta.y * delta.y);
        degenerate = false;
        if (!(len > 0.0)) return;
        const Vec2d dir = delta / len;
        signX = dir.x < 0 ? -1 : 1;
        signY = dir.y < 0 ? -1 : 1;
        if (std::abs(dir.x) < 1e-6 || std::abs(dir.y) < 1e-6) {
            degenerate = true;
            return;
        }
        double t0 = 0.0, t1 = len;
        const double o[2] = {from.x, from.y}, d[2] = {dir.x, dir.y}, l[2] = {lo.x, lo.y},
                     u[2] = {hi.x, hi.y};
        for (int a = 0; a < 2; ++a) {
            double ta = (l[a] - o[a]) / d[a], tb = (u[a] - o[a]) / d[a];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
        }
        if (t0 >= t1) return;
        const Vec2d origin = from + dir * t0;
        const double maxDistance = t1 - t0;
        // At most one cell per unit step along each axis, and the first.
        resize(static_cast<std::size_t>(maxDistance * (std::abs(dir.x) + std::abs(dir.y))) + 8);
        const double invX = 1.0 / dir.x, invY = 1.0 / dir.y;
        // The exit plane of cell c along an axis: c + 1 going up, c going down.
        const double edgeX = dir.x > 0 ? 1.0 - origin.x : -origin.x;
        const double edgeY = dir.y > 0 ? 1.0 - origin.y : -origin.y;
        int cx = static_cast<int>(std::floor(origin.x)),
            cy = static_cast<int>(std::floor(origin.y));
        double t = 0.0;
        std::size_t n = 0;
        while (true) {
            const double tx = (cx + edgeX) * invX;
            const double ty = (cy + edgeY) * invY;
            const double exit = std::min(std::min(tx, ty), maxDistance);
            // Written always, kept where the cell has length (a corner is crossed in one step).
            cellX[n] = cx;
            cellY[n] = cy;
            length[n] = static_cast<float>(exit - t);
            n += exit > t ? 1 : 0;
            t = std::max(t, exit);
            if (exit >= maxDistance || n + 1 >= cellX.size()) break;
            cx += tx <= ty ? signX : 0;
            cy += ty <= tx ? signY : 0;
        }
        resize(n);
        // Plane column and phase of each cell, stepped along (cells move by at most one in x).
        int col = n > 0 ? floorDiv(cellX[0], planes.stride) : 0;
        int phase = n > 0 ? cellX[0] - col * planes.stride : 0;
        for (std::size_t j = 0; j < n; ++j) {
            if (j > 0 && cellX[j] == cellX[j - 1] + signX) {
                phase += signX;
                if (phase == planes.stride) phase = 0, ++col;
                if (phase < 0) phase = planes.stride - 1, --col;
            } else if (j > 0 && cellX[j] != cellX[j - 1]) {
                col = floorDiv(cellX[j], planes.stride);
                phase = cellX[j] - col * planes.stride;
            }
            column[j] = col;
            offset[j] = static_cast<std::int32_t>(
                kStencilLanes + static_cast<std::int64_t>(cellY[j]) * planes.planeSize +
                phase * planes.rowStride + col);
        }
        if (n > 0) {
            minY = std::min(cellY[0], cellY[n - 1]), maxY = std::max(cellY[0], cellY[n - 1]);
            minColumn = std::min(column[0], column[n - 1]);
            maxColumn = std::max(column[0], column[n - 1]);
        }
        // The walk prefetches kStencilPrefetch entries ahead.
        offset.resize(n + kStencilPrefetch, n > 0 ? offset[n - 1] : 0);
        cum.resize(n + 1);
        cum[0] = 0.0;
        for (std::size_t j = 0; j < n; ++j) cum[j + 1] = cum[j] + length[j];
        firstAlong(cellX, signX, firstX);
        firstAlong(cellY, signY, firstY);
    }

    // Entries j with lo <= f[j] <= hi, f monotone in the direction `sign`.
    static std::pair<int, int> where(const std::vector<std::int32_t>& f, int lo, int hi, int sign) {
        if (sign >= 0) {
            return {static_cast<int>(std::lower_bound(f.begin(), f.end(), lo) - f.begin()),
                    static_cast<int>(std::upper_bound(f.begin(), f.end(), hi) - f.begin())};
        }
        const auto first = std::partition_point(f.begin(), f.end(), [&](int v) { return v > hi; });
        const auto last = std::partition_point(f.begin(), f.end(), [&](int v) { return v >= lo; });
        return {static_cast<int>(first - f.begin()), static_cast<int>(last - f.begin())};
    }

  private:
    static void firstAlong(const std::vector<std::int32_t>& cell, int sign,
                           std::vector<std::int32_t>& first) {
        const int n = static_cast<int>(cell.size());
        const int span = n > 0 ? (cell[n - 1] - cell[0]) * sign : 0;
        first.assign(span + 2, n);
        for (int j = n - 1; j >= 0; --j) first[(cell[j] - cell[0]) * sign] = j;
    }

    void resize(std::size_t n) {
        cellX.resize(n), cellY.resize(n), column.resize(n), offset.resize(n), length.resize(n);
    }
};

}  // namespace luxel::gi2d::rc
