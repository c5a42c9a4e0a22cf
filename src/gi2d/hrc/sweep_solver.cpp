#include "gi2d/hrc/sweep_solver.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/near_lights.h"
#include "gi2d/hrc/sweep_buffers.h"
#include "gi2d/hrc/trace_stencil.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/check.h"
#include "luxel/core/half.h"

namespace luxel::gi2d::hrc {
namespace {

namespace shared = gpu::shared;

// Buffers up to this size are kept for the next solve on the same thread (1024^2 needs 40 MiB).
constexpr std::uint64_t kKeptSweepBytes = std::uint64_t{64} << 20;

// Traced cascades actually used for a frame with `levels` cascades.
int tracedFor(int tracedLevels, int levels) {
    return std::clamp(tracedLevels, 1, levels);
}

// The traced rays' stencils below `traced` cascades, with each step's window column and ray
// length resolved (the window holds, per column, one transfer plane set per distinct length).
struct TracedRays {
    std::vector<float> lengths;                              // distinct lengths inside a cell
    std::vector<std::vector<std::vector<TraceStep>>> steps;  // [n][k]
};

// `scaleC0`: cascade 0's cells count with their lengths times LUXEL_HRC_C0_DEPTH_SCALE (§3.1).
TracedRays buildTracedRays(int traced, bool scaleC0) {
    TracedRays rays;
    std::vector<std::vector<std::vector<StencilStep>>> stencils(static_cast<std::size_t>(traced));
    for (int n = 0; n < traced; ++n) {
        for (int k = 0; k <= pow2(n); ++k) {
            stencils[n].push_back(traceStencil(n, k));
            if (n == 0 && scaleC0) {
                for (StencilStep& step : stencils[n].back())
                    step.length *= LUXEL_HRC_C0_DEPTH_SCALE;
            }
            for (const StencilStep& step : stencils[n].back()) {
                if (std::find(rays.lengths.begin(), rays.lengths.end(), step.length) ==
                    rays.lengths.end()) {
                    rays.lengths.push_back(step.length);
                }
            }
        }
    }
    const auto count = static_cast<int>(rays.lengths.size());
    rays.steps.resize(static_cast<std::size_t>(traced));
    for (int n = 0; n < traced; ++n) {
        for (const auto& stencil : stencils[n]) {
            rays.steps[n].emplace_back();
            for (const StencilStep& step : stencil) {
                const auto d = std::find(rays.lengths.begin(), rays.lengths.end(), step.length);
                rays.steps[n].back().push_back(
                    {step.du * count + static_cast<int>(d - rays.lengths.begin()), step.dv});
            }
        }
    }
    return rays;
}

// Built once for every traced count the sweep takes, with and without cascade 0's depth scale.
const TracedRays& tracedRays(int traced, bool scaleC0) {
    static const std::array<std::vector<TracedRays>, 2> all = [] {
        std::array<std::vector<TracedRays>, 2> built;
        for (int s = 0; s < 2; ++s) {
            for (int t = 0; t <= kSweepMaxTracedLevels; ++t) {
                built[s].push_back(buildTracedRays(t, s != 0));
            }
        }
        return built;
    }();
    LUXEL_CHECK(traced >= 1 && traced <= kSweepMaxTracedLevels);
    return all[scaleC0 ? 1 : 0][traced];
}

// Whether cascade 0 takes its depth scale (hrcTracedDepthScale: not where it is the base of ray
// extension). The option decides, as on the GPU, not the count clamped to a short frame's cascades.
bool scalesC0(int tracedLevels) {
    return shared::hrcTracedDepthScale(0, tracedLevels) != 1.0f;
}

// Calls fn(a, b) for the pieces of rows [y0, y1) inside which every row y + offset lies either
// inside [0, rows) for all rows of the piece or for none.
template <std::size_t N, typename Fn>
void forUniformRows(int y0, int y1, int rows, const std::array<int, N>& offsets, int count, Fn fn) {
    std::array<int, 2 * N + 2> cuts{};
    int n = 0;
    cuts[n++] = y0;
    for (int i = 0; i < count; ++i) {
        for (int c : {-offsets[i], rows - offsets[i]}) {
            if (c > y0 && c < y1) cuts[n++] = c;
        }
    }
    cuts[n++] = y1;
    for (int i = 1; i < n; ++i) {  // insertion sort: a handful of cuts
        // The cut moves in a register: swapping neighbours made the compiler load two ints as
        // one word just after storing them apart, a stalled store forward per step.
        const int cut = cuts[i];
        int j = i;
        for (; j > 0 && cuts[j - 1] > cut; --j) cuts[j] = cuts[j - 1];
        cuts[j] = cut;
    }
    for (int i = 0; i + 1 < n; ++i) {
        if (cuts[i] < cuts[i + 1]) fn(cuts[i], cuts[i + 1]);
    }
}

// The planes of cascade n in the chunk of columns [x0, x1): last (x1 - 1) >> n, down to
// ceil(x0 / 2^n), or 1 (plane 0 is never computed, §7.1).
struct ChunkPlanes {
    int x0, x1;
    int last(int n) const { return (x1 - 1) >> n; }
    int first(int n) const { return std::max(1, (x0 + pow2(n) - 1) >> n); }
};

// The top cascades of a chunk are made by angular sectors (§7.1): sector s of cascade n holds
// rays and cones [s, s + 1) 2^n / sectors and reads only sector s of the cascades next to it,
// so one member extends and merges a sector through every cascade, with no barrier between
// cascades, while its planes are still in its cache. The first such cascade has one cone per
// sector; a team of more members than kMaxSectors splits rows instead.
constexpr int kMaxSectors = 16;
int sectorCount(int members) {
    return members <= 4 ? 8 : kMaxSectors;
}

// Member 0's stopwatch: each lap is charged to one pass.
class Laps {
  public:
    explicit Laps(SweepTimes* times) : times_(times), last_(Clock::now()) {}
    void charge(SweepTimes::Pass pass, std::uint64_t bytes) {
        if (times_ == nullptr) return;
        const auto now = Clock::now();
        times_->milliseconds[pass] +=
            std::chrono::duration<double, std::milli>(now - last_).count();
        times_->bytes[pass] += bytes;
        last_ = now;
    }

  private:
    using Clock = std::chrono::steady_clock;
    SweepTimes* times_;
    Clock::time_point last_;
};

class FrustumSweep {
  public:
    FrustumSweep(const Medium2D& medium, const NearLightMask& nearLights, const FrustumFrame& frame,
                 int tracedLevels, SweepBuffers& buffers, Image& beyondSum)
        : medium_(medium),
          nearLights_(nearLights),
          frame_(frame),
          rows_(frame.rows),
          levels_(cascadeCount(frame.length)),
          traced_(tracedFor(tracedLevels, levels_)),
          rays_(tracedRays(traced_, scalesC0(tracedLevels))),
          columns_(buffers.columns),
          tables_(buffers.tables),
          cones_(buffers.cones),
          beyond_(beyondSum) {
        tables_.reshape(levels_, rows_, kSweepChunk);
        cones_.reshape(levels_, rows_, kSweepChunk);
        for (int n = 0; n < levels_; ++n) {
            planes_.push_back(planeCount(frame.length, n));
            weights_.push_back(coneWeights(n));
        }
        for (int kept = 0; kept <= 64; ++kept) {
            weightOf_[static_cast<std::size_t>(kept)] =
                shared::hrcNearRowWeightAt(0, static_cast<unsigned>(kept));
        }
        for (ColumnWindow& window : columns_) {
            window.reshape(pow2(traced_ - 1), rays_.lengths, rows_);
        }
    }

    void run(ThreadTeam& team, int member, SweepTimes* times);

  private:
    bool insideRows(int y) const { return y >= 0 && y < rows_; }
    IntervalRows clip(IntervalRows r, int y) const {
        if (r.plane[0] != nullptr && !insideRows(y + r.offset)) r.plane[0] = nullptr;
        return r;
    }
    ConeRows clip(ConeRows r, int y) const {
        if (r.plane[0] != nullptr && !insideRows(y + r.offset)) r.plane[0] = nullptr;
        return r;
    }
    // The first plane of `r` as clip(r, y) leaves it.
    template <typename Rows>
    const std::uint16_t* clippedPlane(const Rows& r, int y) const {
        return insideRows(y + r.offset) ? r.plane[0] : nullptr;
    }
    // Cone j of upper plane q of cascade n + 1 at row y + offset; the sky beyond the frame.
    ConeRows upper(int n, int q, int j, int offset) const {
        ConeRows r;
        if (n + 1 < levels_ && q < planes_[n + 1]) r = cones_.read(n + 1, q, j, offset);
        r.offset = offset;
        const Rgb fill = medium_.boundaryRadiance * weights_[n][j];
        r.fill[0] = fill.r, r.fill[1] = fill.g, r.fill[2] = fill.b;
        return r;
    }

    std::uint64_t trace(const ColumnWindow& columns, int x, int y0, int y1);
    // Rays [k0, k1) of T_n(p), cones [i0, i1) of R_n(p), rows [y0, y1).
    std::uint64_t extend(int n, int p, int k0, int k1, int y0, int y1);
    std::uint64_t merge(int n, int p, int i0, int i1, int y0, int y1);
    // The bytes the team reads and writes for `rays` rays of an extended plane (two or four
    // sources and the output) and for `cones` cones of R_n(p), every row.
    std::uint64_t extendBytes(int rays) const {
        return static_cast<std::uint64_t>(rays) * rows_ * 12 * 5;
    }
    std::uint64_t mergeBytes(int n, int p, int cones) const;
    // Cascades first .. top of the chunk by angular sectors.
    void sectors(ThreadTeam& team, int member, const ChunkPlanes& chunk, int first, int top,
                 Laps& laps);
    const float* nearRows(int p, int y0, int y1) const;
    std::uint64_t readOut(int u, int plane, int y0, int y1);

    const Medium2D& medium_;
    const NearLightMask& nearLights_;
    std::array<float, 65> weightOf_{};  // hrcNearRowWeightAt(0, kept) for every mask value
    FrustumFrame frame_;
    int rows_, levels_, traced_;
    const TracedRays& rays_;
    std::vector<int> planes_;
    std::vector<std::vector<float>> weights_;
    std::vector<ColumnWindow>& columns_;  // one per team member
    IntervalRing& tables_;
    ConeRing& cones_;
    Image& beyond_;
};

std::uint64_t FrustumSweep::trace(const ColumnWindow& columns, int x, int y0, int y1) {
    thread_local std::vector<CellTransfer> window;
    window.resize(static_cast<std::size_t>(columns.span() * columns.lengths()));
    columns.at(x, window.data());
    std::uint64_t bytes = static_cast<std::uint64_t>(rows_) * 24;  // the column loaded
    for (int n = 0; n < traced_ && (x & (pow2(n) - 1)) == 0; ++n) {
        for (int k = 0; k <= pow2(n); ++k) {
            traceRows(rays_.steps[n][k], window.data(), tables_.write(n, x >> n, k), y0, y1);
            bytes += static_cast<std::uint64_t>(rows_) * 12;
        }
    }
    return bytes;
}

std::uint64_t FrustumSweep::extend(int n, int p, int k0, int k1, int y0, int y1) {
    const bool farExists = 2 * p + 1 < planes_[n - 1];
    for (int k = k0; k < k1; ++k) {
        const int lo = k >> 1, hi = (k + 1) >> 1;
        const bool twoPaths = lo != hi;
        const IntervalRows nearA = tables_.read(n - 1, 2 * p, lo);
        const IntervalRows nearB = tables_.read(n - 1, 2 * p, hi);
        IntervalRows farA, farB;
        if (farExists) {
            farA = tables_.read(n - 1, 2 * p + 1, hi, shared::hrcRayOffsetY(n - 1, lo));
            farB = tables_.read(n - 1, 2 * p + 1, lo, shared::hrcRayOffsetY(n - 1, hi));
        }
        const std::array<int, 2> offsets{farA.offset, farB.offset};
        forUniformRows(y0, y1, rows_, offsets, farExists ? 2 : 0, [&](int a, int b) {
            extendRows(nearA, clip(farA, a), nearB, clip(farB, a), twoPaths, tables_.write(n, p, k),
                       a, b);
        });
    }
    return extendBytes(k1 - k0);
}

const float* FrustumSweep::nearRows(int p, int y0, int y1) const {
    // Cascade 0's plane p is read out for pixel p - 1 (§6.2): its near-light mask byte weighs
    // the near probe's row blend (§12.3). Frame column p - 1 is a canvas column in the +-x
    // frames and a canvas row in the +-y frames; one without a light nearby keeps the whole
    // blend, the constant weight. Padded for whole-vector loads.
    int cx = 0, cy = 0;
    frame_.toCanvas(p - 1, 0, cx, cy);
    const bool alongColumn = frame_.frustum == Frustum::PlusX || frame_.frustum == Frustum::MinusX;
    if (alongColumn ? !nearLights_.columnNear(cx) : !nearLights_.rowNear(cy)) return nullptr;
    thread_local std::vector<float> weights;
    weights.resize(static_cast<std::size_t>(rows_ + kSweepRowPad));
    // The frame's rows step through the canvas by a fixed stride (one pixel, or one row).
    int nx = 0, ny = 0;
    frame_.toCanvas(p - 1, 1, nx, ny);
    const std::ptrdiff_t width = nearLights_.width();
    const std::ptrdiff_t stride = (ny - cy) * width + (nx - cx);
    const std::uint8_t* mask = nearLights_.bytes().data() + cy * width + cx;
    for (int y = y0; y < y1; ++y) {
        weights[static_cast<std::size_t>(y)] = weightOf_[mask[y * stride]];
    }
    return weights.data();
}

std::uint64_t FrustumSweep::merge(int n, int p, int i0, int i1, int y0, int y1) {
    const bool odd = (p & 1) != 0;
    const float second = shared::hrcSecondRowWeight(n);
    const float nearSecond = shared::hrcNearRowWeight(n);
    const bool nextExists = p + 1 < planes_[n];
    for (int i = i0; i < i1; ++i) {
        MergeSide sides[2];
        std::array<int, 12> offsets{};
        int count = 0;
        for (int s = 0; s < 2; ++s) {
            const int k = i + s, j = 2 * i + s, dy = shared::hrcRayOffsetY(n, k);
            const int axis = shared::hrcTowardsAxis(s);
            MergeSide& side = sides[s];
            side.weight = weights_[n][j];
            side.here = tables_.read(n, p, k);
            if (odd) {  // Eq 14: the ray ends on upper plane (p + 1) / 2
                side.upperA = upper(n, (p + 1) / 2, j, dy);
                side.upperA2 = upper(n, (p + 1) / 2, j, dy + axis);
            } else {  // Eq 15-17: near upper plane p / 2, far p / 2 + 1
                if (nextExists) side.next = tables_.read(n, p + 1, k, dy);
                side.upperA = upper(n, p / 2, j, 0);
                side.upperA2 = upper(n, p / 2, j, dy);
                side.upperB = upper(n, p / 2 + 1, j, 2 * dy);
                side.upperB2 = upper(n, p / 2 + 1, j, 2 * dy + axis);
                side.upperB3 = upper(n, p / 2 + 1, j, 2 * dy + 2 * axis);
                if (nextExists) offsets[count++] = dy;
                offsets[count++] = side.upperB.offset;
                offsets[count++] = side.upperB2.offset;
                offsets[count++] = side.upperB3.offset;
            }
            offsets[count++] = side.upperA.offset;
            offsets[count++] = side.upperA2.offset;
        }
        std::uint16_t* const out[3] = {cones_.plane(n, p, i, 0), cones_.plane(n, p, i, 1),
                                       cones_.plane(n, p, i, 2)};
        const float* nearRowsHere = n == 0 && !odd ? nearRows(p, y0, y1) : nullptr;
        // Each piece clears the sources outside the frame; only those pointers are reset per
        // piece, not the whole sides copied.
        MergeSide clipped[2] = {sides[0], sides[1]};
        forUniformRows(y0, y1, rows_, offsets, count, [&](int a, int b) {
            for (int s = 0; s < 2; ++s) {
                const MergeSide& side = sides[s];
                MergeSide& to = clipped[s];
                to.next.plane[0] = clippedPlane(side.next, a);
                to.upperA.plane[0] = clippedPlane(side.upperA, a);
                to.upperA2.plane[0] = clippedPlane(side.upperA2, a);
                to.upperB.plane[0] = clippedPlane(side.upperB, a);
                to.upperB2.plane[0] = clippedPlane(side.upperB2, a);
                to.upperB3.plane[0] = clippedPlane(side.upperB3, a);
            }
            mergeRows(odd, clipped[0], clipped[1], second, nearSecond, nearRowsHere, out, a, b);
        });
    }
    return mergeBytes(n, p, i1 - i0);
}

std::uint64_t FrustumSweep::mergeBytes(int n, int p, int cones) const {
    // Per cone: its two rays here (and on the next plane), 2 or 5 upper rows each (one fewer
    // from cascade 2 up, where the near probe is one row), the output (intervals 12 bytes,
    // cones 6).
    // Cascade 0's even planes also read the near-light mask, a byte per row.
    const bool odd = (p & 1) != 0;
    const int evenUpperRows = shared::hrcNearRowWeight(n) == 0.0f ? 4 : 5;
    return static_cast<std::uint64_t>(cones) * rows_ *
               (odd ? 2 * 12 + 4 * 6 + 6 : 4 * 12 + 2 * evenUpperRows * 6 + 6) +
           (n == 0 && !odd ? static_cast<std::uint64_t>(rows_) : 0);
}

std::uint64_t FrustumSweep::readOut(int u, int plane, int y0, int y1) {
    // Each member gathers a block of read-out columns for its rows, then adds the block to the
    // canvas along canvas rows (for the ±x frames a frame column is a canvas column).
    constexpr int kBlock = ColumnWindow::kColumnBlock;
    thread_local std::vector<float> pending;
    const int band = y1 - y0;
    pending.resize(static_cast<std::size_t>(kBlock) * 3 * band);
    auto gathered = [&](int w, int c) {
        return pending.data() + (static_cast<std::size_t>(w % kBlock) * 3 + c) * band;
    };
    const Rgb sky = medium_.boundaryRadiance * LUXEL_HRC_QUARTER_TURN;
    for (int c = 0; c < 3; ++c) {
        if (plane >= 0) {
            halvesToFloats(cones_.plane(0, plane, 0, c) + y0, gathered(u, c),
                           static_cast<std::size_t>(band));
        } else {
            std::fill_n(gathered(u, c), band, sky[c]);
        }
    }
    if (u % kBlock != 0) return static_cast<std::uint64_t>(band) * 18;  // binary16 in, float out
    const int last = std::min(u + kBlock - 1, frame_.length - 1);
    const int width = beyond_.width(), height = beyond_.height();
    auto pixel = [&](int x, int y) {
        return beyond_.data() + (static_cast<std::size_t>(y) * width + x) * 3;
    };
    // The canvas pixel of frame pixel (w, v), as FrustumFrame::toCanvas maps it.
    switch (frame_.frustum) {
        case Frustum::PlusX:
        case Frustum::MinusX: {
            // Each v is another canvas row, holding the block's columns side by side (in
            // reverse order for -x): float k of that stretch comes from pending plane
            // index[k] / band, at v - y0.
            const int columns = last - u + 1;
            std::array<std::int32_t, kBlock * 3> index{};
            for (int q = 0; q < columns; ++q) {
                const int w = frame_.frustum == Frustum::PlusX ? u + q : last - q;
                for (int c = 0; c < 3; ++c) {
                    index[static_cast<std::size_t>(3 * q + c)] =
                        static_cast<std::int32_t>(gathered(w, c) - pending.data());
                }
            }
            const int lo = frame_.frustum == Frustum::PlusX ? u : width - 1 - last;
            addGatheredRows(pixel(lo, y0), static_cast<std::ptrdiff_t>(width) * 3, pending.data(),
                            1, index.data(), columns * 3, band, kPrefetchRows);
            break;
        }
        case Frustum::PlusY:
        case Frustum::MinusY:
            for (int w = u; w <= last; ++w) {
                float* row = pixel(0, frame_.frustum == Frustum::PlusY ? w : height - 1 - w);
                const float* const from[3] = {gathered(w, 0), gathered(w, 1), gathered(w, 2)};
                addRgbPlanes(row + 3 * static_cast<std::ptrdiff_t>(y0), from, y1 - y0);
            }
            break;
    }
    return static_cast<std::uint64_t>(band) * (18 + (last - u + 1) * 24);
}

void FrustumSweep::sectors(ThreadTeam& team, int member, const ChunkPlanes& chunk, int first,
                           int top, Laps& laps) {
    const int members = team.size(), count = sectorCount(members);
    // Ray s 2^n / count of cascade n, where sector s begins, is even: it extends along one path,
    // from ray s 2^(n-1) / count below (§4). So each boundary between two sectors is a chain of
    // rays, one per plane, made before either sector.
    for (int s = 1 + member; s < count; s += members) {
        for (int n = first; n <= top; ++n) {
            const int k = s * (pow2(n) / count);
            for (int p = chunk.last(n); p >= chunk.first(n); --p) extend(n, p, k, k + 1, 0, rows_);
        }
    }
    team.sync();
    laps.charge(SweepTimes::Extend, 0);
    for (int s = member; s < count; s += members) {
        for (int n = first; n <= top; ++n) {
            const int per = pow2(n) / count, a = s * per;
            // Ray a is the chain's (sector 0's is ray 0); the last sector also makes ray 2^n.
            const int k0 = s == 0 ? 0 : a + 1, k1 = s == count - 1 ? a + per + 1 : a + per;
            for (int p = chunk.last(n); p >= chunk.first(n); --p) extend(n, p, k0, k1, 0, rows_);
        }
        laps.charge(SweepTimes::Extend, 0);
        for (int n = top; n >= first; --n) {
            const int per = pow2(n) / count;
            for (int p = chunk.last(n); p >= chunk.first(n); --p) {
                merge(n, p, s * per, (s + 1) * per, 0, rows_);
            }
        }
        laps.charge(SweepTimes::Merge, 0);
    }
    // The merge of the cascade below reads every sector.
    team.sync();
    // The team's bytes, charged once.
    std::uint64_t extended = 0, merged = 0;
    for (int n = first; n <= top; ++n) {
        for (int p = chunk.last(n); p >= chunk.first(n); --p) {
            extended += extendBytes(pow2(n) + 1);
            merged += mergeBytes(n, p, pow2(n));
        }
    }
    laps.charge(SweepTimes::Merge, merged);  // the wait above was the merge's
    laps.charge(SweepTimes::Extend, extended);
}

void FrustumSweep::run(ThreadTeam& team, int member, SweepTimes* times) {
    const int y0 = team.bandBegin(member, rows_), y1 = team.bandBegin(member + 1, rows_);
    // A member traces its own rows, so it loads the medium for them and the rows its stencils
    // reach beyond them.
    ColumnWindow& window = columns_[member];
    const int reach = window.span();
    const int h0 = std::max(0, y0 - reach), h1 = std::min(rows_, y1 + reach);
    const int length = frame_.length;
    Laps laps(times);
    // The first cascade the sectors make (0: none): the one with a cone per sector, or the first
    // extended one. A lone member meets no one, and its rows are every row: it keeps the
    // cascade-by-cascade order (1024^2: the extend 37 ms against 40 by sectors).
    const int bySectors =
        team.size() > 1 && team.size() <= kMaxSectors
            ? std::max(traced_, std::countr_zero(static_cast<unsigned>(sectorCount(team.size()))))
            : 0;
    // The last pixel's read-out plane lies beyond the frame: it sees the sky (§6.2).
    readOut(length - 1, -1, y0, y1);
    // Chunks of kSweepChunk columns from the far end; in each, cascade by cascade, so the team
    // meets once per cascade and chunk rather than once per cascade and column (§7.1). Plane 0 of
    // every cascade (x = 0) is never computed: pixel x reads plane x + 1 out, and planes p >= 1
    // read only planes >= 1 (§7.1), so nothing it holds reaches the image.
    for (int x0 = (length - 1) / kSweepChunk * kSweepChunk; x0 >= 0; x0 -= kSweepChunk) {
        const int x1 = std::min(length, x0 + kSweepChunk);
        std::uint64_t traced = 0;
        for (int x = x1 - 1; x >= std::max(x0, 1); --x) {
            window.load(medium_, frame_, x, h0, h1);
            traced += trace(window, x, y0, y1);
        }
        team.sync();
        laps.charge(SweepTimes::Trace, traced);
        const ChunkPlanes chunk{x0, x1};
        auto lastPlane = [&](int n) { return chunk.last(n); };
        auto firstPlane = [&](int n) { return chunk.first(n); };
        // The cascades [bySectors, top] have planes here, made by sectors; none above.
        int top = -1;
        if (bySectors) {
            for (int n = bySectors; n < levels_ && lastPlane(n) >= firstPlane(n); ++n) top = n;
        }
        auto inSectors = [&](int n) { return n >= bySectors && n <= top; };
        for (int n = traced_; n < levels_; ++n) {
            if (lastPlane(n) < firstPlane(n) || inSectors(n)) continue;
            std::uint64_t bytes = 0;
            for (int p = lastPlane(n); p >= firstPlane(n); --p) {
                bytes += extend(n, p, 0, pow2(n) + 1, y0, y1);
            }
            team.sync();
            laps.charge(SweepTimes::Extend, bytes);
        }
        if (top >= 0) sectors(team, member, chunk, bySectors, top, laps);
        for (int n = levels_ - 1; n >= 0; --n) {
            if (lastPlane(n) < firstPlane(n) || inSectors(n)) continue;
            std::uint64_t bytes = 0;
            for (int p = lastPlane(n); p >= firstPlane(n); --p) {
                bytes += merge(n, p, 0, pow2(n), y0, y1);
            }
            if (n > 0) team.sync();
            laps.charge(SweepTimes::Merge, bytes);
        }
        std::uint64_t read = 0;
        for (int x = x1 - 1; x >= std::max(x0, 1); --x) read += readOut(x - 1, x, y0, y1);
        // The next chunk overwrites ring slots that other members may still be reading.
        team.sync();
        laps.charge(SweepTimes::Readout, read);
    }
}

}  // namespace

void sweepFrustums(const Medium2D& medium, LightScores scores, const HrcOptions& options,
                   int threads, Image& beyondSum, SweepTimes* times) {
    LUXEL_CHECK(medium.absorption.channels() == 3 && medium.emission.channels() == 3 &&
                beyondSum.channels() == 3);
    const int frustums = std::popcount(options.frustumMask & 0xFu);
    int done = 0;
    // Small buffers stay with the calling thread for its next solve (a viewer solves every frame:
    // fresh pages would cost a fault each); large ones are given back.
    thread_local SweepBuffers kept;
    SweepBuffers buffers = std::move(kept);
    kept = {};
    buffers.nearLights.build(scores);
    scores.release();
    const NearLightMask& nearLights = buffers.nearLights;
    for (int r = 0; r < 4; ++r) {
        if (!(options.frustumMask & (1u << r))) continue;
        const FrustumFrame frame =
            makeFrame(static_cast<Frustum>(r), medium.width(), medium.height());
        const int members = std::min(threads, frame.rows);
        buffers.columns.resize(static_cast<std::size_t>(members));
        FrustumSweep sweep(medium, nearLights, frame, options.tracedLevels, buffers, beyondSum);
        ThreadTeam::run(members, [&](int member, ThreadTeam& team) {
            sweep.run(team, member, member == 0 ? times : nullptr);
        });
        if (options.onProgress) options.onProgress(++done, frustums);
    }
    if (sweepMemory(medium.width(), medium.height(), options.tracedLevels, threads).total() <=
        kKeptSweepBytes) {
        kept = std::move(buffers);
    }
}

SweepMemory sweepMemory(int width, int height, int tracedLevels, int threads) {
    SweepMemory most;
    for (int r = 0; r < 2; ++r) {
        const FrustumFrame frame = makeFrame(static_cast<Frustum>(r), width, height);
        const int levels = cascadeCount(frame.length);
        const int traced = tracedFor(tracedLevels, levels);
        SweepMemory m;
        m.intervals = IntervalRing::bytesFor(levels, frame.rows, kSweepChunk);
        m.cones = ConeRing::bytesFor(levels, frame.rows, kSweepChunk);
        // One window per team member; each loads its band of rows (as ThreadTeam::bandBegin
        // splits them) and the rows its stencils reach beyond it.
        const int members = std::clamp(threads, 1, frame.rows);
        const int span = pow2(traced - 1);
        const int lengths =
            static_cast<int>(tracedRays(traced, scalesC0(tracedLevels)).lengths.size());
        int band = 0, reached = 0;
        for (int i = 0; i < members; ++i) {
            const auto begin = [&](int j) {
                return static_cast<int>(static_cast<long long>(frame.rows) * j / members);
            };
            band = std::max(band, begin(i + 1) - begin(i));
            reached = std::max(
                reached, std::min(frame.rows, begin(i + 1) + span) - std::max(0, begin(i) - span));
        }
        // Per member: its window, the transfer planes one trace step sees and the read-out's
        // block of gathered columns (readOut).
        m.columns =
            static_cast<std::uint64_t>(members) *
            (ColumnWindow::bytesFor(span, lengths, frame.rows, reached) +
             static_cast<std::uint64_t>(span) * lengths * sizeof(CellTransfer) +
             static_cast<std::uint64_t>(ColumnWindow::kColumnBlock) * 3 * band * sizeof(float));
        // The buffers keep their allocations from frame to frame: the larger of each.
        most.intervals = std::max(most.intervals, m.intervals);
        most.cones = std::max(most.cones, m.cones);
        most.columns = std::max(most.columns, m.columns);
    }
    most.nearLights = NearLightMask::hostBytesFor(width, height);
    return most;
}

}  // namespace luxel::gi2d::hrc
