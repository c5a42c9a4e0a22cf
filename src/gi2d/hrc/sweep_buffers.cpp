#include "gi2d/hrc/sweep_buffers.h"

#include <algorithm>
#include <utility>

#include "luxel/core/memory.h"

namespace luxel::gi2d::hrc {

void ColumnWindow::reshape(int span, std::vector<float> lengths, int rows) {
    span_ = span;
    rows_ = rows;
    lengths_ = std::move(lengths);
    pad_ = span + 1;
    stride_ = rows + 2 * (span + 1) + kSweepRowPad;
    data_.resize(static_cast<std::size_t>(span) * lengths_.size() * 6 * stride_);
    // Vacuum everywhere: t = 1, L = 0.
    for (std::size_t p = 0; p < data_.size() / stride_; ++p) {
        std::fill_n(data_.begin() + static_cast<std::ptrdiff_t>(p * stride_), stride_,
                    p % 6 < 3 ? 1.0f : 0.0f);
    }
}

std::uint64_t ColumnWindow::bytesFor(int span, int lengths, int rows, int bandRows) {
    return (static_cast<std::uint64_t>(span) * lengths * 6 *
                (rows + 2 * (span + 1) + kSweepRowPad) +
            static_cast<std::uint64_t>(kColumnBlock) * 6 * (bandRows + kSweepRowPad)) *
           sizeof(float);
}

void ColumnWindow::load(const Medium2D& medium, const FrustumFrame& frame, int x, int v0, int v1) {
    if (v1 <= v0) return;
    // The block holds the member's rows only: row v at v - v0.
    const std::size_t rowStride = static_cast<std::size_t>(v1 - v0) + kSweepRowPad;
    if (block_.size() < kColumnBlock * 6 * rowStride) block_.resize(kColumnBlock * 6 * rowStride);
    auto raw = [&](int column, int c) {
        return block_.data() + (static_cast<std::size_t>(column) * 6 + c) * rowStride;
    };
    // The sweep runs x downwards: a block opens at its last column (or the frame's).
    if (x % kColumnBlock == kColumnBlock - 1 || x == frame.length - 1) {
        const int first = x - x % kColumnBlock;
        const float* sigma = medium.absorption.data();
        const float* emission = medium.emission.data();
        const std::ptrdiff_t width = medium.width();
        // Frame pixel (u, v) is canvas pixel (cx, cy) by FrustumFrame::toCanvas, an affine map:
        // its RGB triple starts (cy · width + cx) · 3 floats into either image, and a step of u
        // or of v moves that by a fixed number of floats.
        int cx0, cy0, cxU, cyU, cxV, cyV;
        frame.toCanvas(first, v0, cx0, cy0);
        frame.toCanvas(first + 1, v0, cxU, cyU);
        frame.toCanvas(first, v0 + 1, cxV, cyV);
        const std::ptrdiff_t origin = (cy0 * width + cx0) * 3;
        const std::ptrdiff_t stepU = ((cyU - cy0) * width + (cxU - cx0)) * 3;
        const std::ptrdiff_t stepV = ((cyV - cy0) * width + (cxV - cx0)) * 3;
        const int columns = x - first + 1, count = v1 - v0;
        float* out[kColumnBlock][6];
        for (int j = 0; j < columns; ++j) {
            for (int c = 0; c < 6; ++c) out[j][c] = raw(j, c);
        }
        // Canvas rows are contiguous: along them (u) for the ±x frames, down the frame column (v)
        // else; the loop runs along the canvas row in the inner loop.
        const bool alongX = frame.frustum == Frustum::PlusX || frame.frustum == Frustum::MinusX;
        if (alongX) {
            // Each frame row is another canvas row: the prefetcher does not follow strides of a
            // canvas row, so the block's rows a few ahead are fetched by hand.
            const std::ptrdiff_t blockFloats = std::ptrdiff_t(columns) * 3;
            for (int i = 0; i < count; ++i) {
                const std::ptrdiff_t row = origin + i * stepV;
                if (i + kPrefetchRows < count) {
                    const std::ptrdiff_t ahead = row + kPrefetchRows * stepV;
                    const std::ptrdiff_t lo = std::min(ahead, ahead + (columns - 1) * stepU);
                    prefetchFloats(sigma + lo, blockFloats, false);
                    prefetchFloats(emission + lo, blockFloats, false);
                }
                for (int j = 0; j < columns; ++j) {
                    const std::ptrdiff_t k = row + j * stepU;
                    for (int c = 0; c < 3; ++c) {
                        out[j][c][i] = sigma[k + c];
                        out[j][3 + c][i] = emission[k + c];
                    }
                }
            }
        } else {
            for (int j = 0; j < columns; ++j) {
                const std::ptrdiff_t column = origin + j * stepU;
                float* const* to = out[j];
                for (int i = 0; i < count; ++i) {
                    const std::ptrdiff_t k = column + i * stepV;
                    for (int c = 0; c < 3; ++c) {
                        to[c][i] = sigma[k + c];
                        to[3 + c][i] = emission[k + c];
                    }
                }
            }
        }
    }
    const int column = x % kColumnBlock;
    const float* const s[3] = {raw(column, 0), raw(column, 1), raw(column, 2)};
    const float* const e[3] = {raw(column, 3), raw(column, 4), raw(column, 5)};
    const int slot = x & (span_ - 1);
    for (int d = 0; d < lengths(); ++d) {
        float* base = data_.data() + v0;
        float* const t[3] = {base + offset(slot, d, 0), base + offset(slot, d, 1),
                             base + offset(slot, d, 2)};
        float* const l[3] = {base + offset(slot, d, 3), base + offset(slot, d, 4),
                             base + offset(slot, d, 5)};
        cellTransferRows(s, e, lengths_[d], t, l, v1 - v0);
    }
}

void ColumnWindow::at(int x, CellTransfer* out) const {
    for (int du = 0; du < span_; ++du) {
        for (int d = 0; d < lengths(); ++d) {
            CellTransfer& cell = out[du * lengths() + d];
            for (int c = 0; c < 6; ++c)
                cell.plane[c] = data_.data() + offset((x + du) & (span_ - 1), d, c);
        }
    }
}

int ringSlots(int n, int levels, int chunk) {
    if (n == levels - 1) return 1;
    return std::max(2, (chunk >> n) + 1);
}

namespace {

// Slots per cascade and the start of each cascade's slots in one buffer of `perPlane(n)` values
// per plane.
template <typename PerPlane>
std::size_t layOut(int levels, int chunk, PerPlane perPlane, std::vector<int>& slots,
                   std::vector<std::size_t>& starts) {
    slots.resize(static_cast<std::size_t>(levels));
    starts.resize(static_cast<std::size_t>(levels));
    std::size_t total = 0;
    for (int n = 0; n < levels; ++n) {
        slots[n] = ringSlots(n, levels, chunk);
        starts[n] = total;
        total += static_cast<std::size_t>(slots[n]) * perPlane(n);
    }
    return total;
}

std::size_t intervalsPerPlane(int n, int rows) {
    return ((static_cast<std::size_t>(1) << n) + 1) * 6 * rows;
}

std::size_t conesPerPlane(int n, int rows) {
    return (static_cast<std::size_t>(1) << n) * 3 * rows;
}

}  // namespace

void IntervalRing::reshape(int levels, int rows, int chunk) {
    rows_ = rows;
    const std::size_t total = layOut(
        levels, chunk, [&](int n) { return intervalsPerPlane(n, rows); }, slots_, levelStart_);
    resizeOnHugePages(data_, total + kSweepRowPad);
}

std::uint64_t IntervalRing::bytesFor(int levels, int rows, int chunk) {
    std::vector<int> slots;
    std::vector<std::size_t> starts;
    const std::size_t total = layOut(
        levels, chunk, [&](int n) { return intervalsPerPlane(n, rows); }, slots, starts);
    return (total + kSweepRowPad) * sizeof(std::uint16_t);
}

IntervalRows IntervalRing::read(int n, int p, int k, int offset) const {
    IntervalRows r;
    const std::uint16_t* base = data_.data() + index(n, p, k);
    for (int c = 0; c < 6; ++c) r.plane[c] = base + static_cast<std::size_t>(c) * rows_;
    r.offset = offset;
    return r;
}

IntervalRowsOut IntervalRing::write(int n, int p, int k) {
    IntervalRowsOut r;
    std::uint16_t* base = data_.data() + index(n, p, k);
    for (int c = 0; c < 6; ++c) r.plane[c] = base + static_cast<std::size_t>(c) * rows_;
    return r;
}

void ConeRing::reshape(int levels, int rows, int chunk) {
    rows_ = rows;
    const std::size_t total = layOut(
        levels, chunk, [&](int n) { return conesPerPlane(n, rows); }, slots_, levelStart_);
    resizeOnHugePages(data_, total + kSweepRowPad);
}

std::uint64_t ConeRing::bytesFor(int levels, int rows, int chunk) {
    std::vector<int> slots;
    std::vector<std::size_t> starts;
    const std::size_t total = layOut(
        levels, chunk, [&](int n) { return conesPerPlane(n, rows); }, slots, starts);
    return (total + kSweepRowPad) * sizeof(std::uint16_t);
}

ConeRows ConeRing::read(int n, int p, int i, int offset) const {
    ConeRows r;
    const std::uint16_t* base = data_.data() + index(n, p, i);
    for (int c = 0; c < 3; ++c) r.plane[c] = base + static_cast<std::size_t>(c) * rows_;
    r.offset = offset;
    return r;
}

std::uint16_t* ConeRing::plane(int n, int p, int i, int channel) {
    return data_.data() + index(n, p, i) + static_cast<std::size_t>(channel) * rows_;
}

}  // namespace luxel::gi2d::hrc
