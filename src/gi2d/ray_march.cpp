// Exact DDA ray integration through the 2D medium with uniform-block skipping.
#include "luxel/gi2d/ray_march.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "gi2d/material_bits.h"
#include "luxel/core/check.h"

namespace luxel::gi2d {

namespace {
constexpr int kMaxBlockLevel = 12;

// floor() for coordinates within the canvas; std::floor is a library call without SSE4.1.
inline int floorToInt(double x) {
    const int i = static_cast<int>(x);
    return i - (x < i ? 1 : 0);
}

// The cell recomputed from an exit point, never behind the current one: at a corner, rounding can
// put the point just behind a border the ray has already crossed, and stepping back there would
// bounce between two cells forever.
inline int forwardOnly(int current, int recomputed, double direction) {
    if (direction > 0) return std::max(current, recomputed);
    if (direction < 0) return std::min(current, recomputed);
    return recomputed;
}

}  // namespace

RayMarcher::RayMarcher(const Medium2D& medium)
    : width_(medium.width()), height_(medium.height()), boundary_(medium.boundaryRadiance) {
    LUXEL_CHECK_LE(static_cast<std::uint64_t>(width_) * height_, kMaxPixels);
    buildPalette(medium);
    buildBlockLevels();
}

std::uint64_t RayMarcher::bytesFor(std::uint64_t width, std::uint64_t height) {
    return width * height * (sizeof(std::uint32_t) + sizeof(Material) + 8);
}

void RayMarcher::buildPalette(const Medium2D& medium) {
    grid_.resize(static_cast<std::size_t>(width_) * height_);
    std::unordered_map<MaterialBits, std::uint32_t, MaterialBitsHash> ids;
    MaterialBits previous{};
    std::uint32_t previousId = std::numeric_limits<std::uint32_t>::max();
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const Rgb s = medium.absorption.rgb(x, y), e = medium.emission.rgb(x, y);
            const Material m{{s.r, s.g, s.b}, {e.r, e.g, e.b}};
            MaterialBits bits;
            std::memcpy(bits.words, &m, sizeof bits.words);
            // Neighbours usually share a material: skip the hash lookup for runs.
            if (previousId == std::numeric_limits<std::uint32_t>::max() || !(bits == previous)) {
                auto [it, inserted] =
                    ids.try_emplace(bits, static_cast<std::uint32_t>(palette_.size()));
                if (inserted) palette_.push_back(m);
                previous = bits;
                previousId = it->second;
            }
            grid_[static_cast<std::size_t>(y) * width_ + x] = previousId << kLevelBits;
        }
    }
}

void RayMarcher::buildBlockLevels() {
    // uniform[k] marks aligned blocks of side 2^k (inside the canvas) with one material; a block
    // is uniform when its 4 children are and their first pixels share the material.
    std::vector<std::uint8_t> previous(grid_.size(), 1), current;
    int prevW = width_;
    for (int k = 1; k <= kMaxBlockLevel; ++k) {
        const int w = width_ >> k, h = height_ >> k;
        if (w == 0 || h == 0) break;
        current.assign(static_cast<std::size_t>(w) * h, 0);
        bool any = false;
        const int half = 1 << (k - 1);
        for (int by = 0; by < h; ++by) {
            for (int bx = 0; bx < w; ++bx) {
                auto child = [&](int i, int j) {
                    return previous[static_cast<std::size_t>(2 * by + j) * prevW + 2 * bx + i];
                };
                if (!(child(0, 0) && child(1, 0) && child(0, 1) && child(1, 1))) continue;
                auto idAt = [&](int i, int j) {
                    return grid_[static_cast<std::size_t>((by << k) + j * half) * width_ +
                                 (bx << k) + i * half] >>
                           kLevelBits;
                };
                const std::uint32_t first = idAt(0, 0);
                if (first != idAt(1, 0) || first != idAt(0, 1) || first != idAt(1, 1)) continue;
                current[static_cast<std::size_t>(by) * w + bx] = 1;
                any = true;
                const std::uint32_t word = (first << kLevelBits) | static_cast<std::uint32_t>(k);
                for (int y = by << k; y < (by + 1) << k; ++y) {
                    std::fill_n(&grid_[static_cast<std::size_t>(y) * width_ + (bx << k)], 1 << k,
                                word);
                }
            }
        }
        if (!any) break;
        previous.swap(current);
        prevW = w;
    }
}

RaySegment RayMarcher::march(Vec2d origin, Vec2d direction, double maxDistance, float cutoff,
                             float depthScale) const {
    return marchImpl(origin, direction, maxDistance, cutoff, true, depthScale);
}

RaySegment RayMarcher::segment(Vec2d from, Vec2d to, bool* leavesCanvas) const {
    const Vec2d delta = to - from;
    const double len = length(delta);
    auto outside = [&](Vec2d p) { return p.x < 0 || p.y < 0 || p.x > width_ || p.y > height_; };
    if (leavesCanvas) *leavesCanvas = outside(to);
    if (len <= 0.0) return {};
    const Vec2d dir = delta / len;
    // Clip [0, len] to the canvas box (slab test).
    double t0 = 0.0, t1 = len;
    const double lo[2] = {0.0, 0.0},
                 hi[2] = {static_cast<double>(width_), static_cast<double>(height_)};
    const double o[2] = {from.x, from.y}, d[2] = {dir.x, dir.y};
    for (int a = 0; a < 2; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < lo[a] || o[a] > hi[a]) return {};
            continue;
        }
        double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (t0 >= t1) return {};
    Vec2d start = from + dir * t0;
    start.x = std::clamp(start.x, 0.0, static_cast<double>(width_));
    start.y = std::clamp(start.y, 0.0, static_cast<double>(height_));
    return marchImpl(start, dir, t1 - t0, 1e-6f, false);
}

RaySegment RayMarcher::marchImpl(Vec2d origin, Vec2d direction, double maxDistance, float cutoff,
                                 bool addBoundary, float depthScale) const {
    LUXEL_DCHECK(std::abs(length(direction) - 1.0) < 1e-6);
    LUXEL_DCHECK(origin.x >= 0 && origin.y >= 0 && origin.x <= width_ && origin.y <= height_);

    const double inf = std::numeric_limits<double>::infinity();
    const double invX = direction.x != 0.0 ? 1.0 / direction.x : inf;
    const double invY = direction.y != 0.0 ? 1.0 / direction.y : inf;
    int cx = std::min(static_cast<int>(std::floor(origin.x)), width_ - 1);
    int cy = std::min(static_cast<int>(std::floor(origin.y)), height_ - 1);

    float radiance[3] = {0, 0, 0};
    float transmittance[3] = {1, 1, 1};
    // The pending run of one material and its total length.
    std::uint32_t run = std::numeric_limits<std::uint32_t>::max();
    double runLength = 0.0;
    auto flushRun = [&] {
        if (run == std::numeric_limits<std::uint32_t>::max() || runLength <= 0.0) return;
        const Material& m = palette_[run];
        const float length = static_cast<float>(runLength) * depthScale;
        // Grey absorption (the common case) needs one exp for all channels.
        const bool grey = m.sigma[0] == m.sigma[1] && m.sigma[1] == m.sigma[2];
        const float greyT = grey ? std::exp(-m.sigma[0] * length) : 0.0f;
        for (int c = 0; c < 3; ++c) {
            if (m.sigma[c] == 0.0f) continue;  // vacuum: t = 1 and nothing emitted
            const float t = grey ? greyT : std::exp(-m.sigma[c] * length);
            radiance[c] += transmittance[c] * m.emission[c] * (1.0f - t);
            transmittance[c] *= t;
        }
    };

    double t = 0.0;
    bool leftCanvas = false;
    while (true) {
        const std::uint32_t word = grid_[static_cast<std::size_t>(cy) * width_ + cx];
        const int k = static_cast<int>(word & kLevelMask);
        const std::uint32_t material = word >> kLevelBits;
        const int size = 1 << k;
        const int bx0 = (cx >> k) << k, by0 = (cy >> k) << k;
        // Distances to the block's exit planes along each axis.
        const double tx = direction.x > 0   ? (bx0 + size - origin.x) * invX
                          : direction.x < 0 ? (bx0 - origin.x) * invX
                                            : inf;
        const double ty = direction.y > 0   ? (by0 + size - origin.y) * invY
                          : direction.y < 0 ? (by0 - origin.y) * invY
                                            : inf;
        const double exit = std::min(std::min(tx, ty), maxDistance);
        if (material != run) {
            flushRun();
            if (std::max(transmittance[0], std::max(transmittance[1], transmittance[2])) < cutoff) {
                run = std::numeric_limits<std::uint32_t>::max();
                break;
            }
            run = material;
            runLength = 0.0;
        }
        runLength += std::max(exit - t, 0.0);
        t = exit;
        if (t >= maxDistance) break;

        // Step into the neighbouring cell across the exit plane(s). The coordinate along the
        // other axis is recomputed from the exit point, since a block step may move it.
        const bool stepX = tx <= ty, stepY = ty <= tx;
        if (stepX) {
            cx = direction.x > 0 ? bx0 + size : bx0 - 1;
        } else {
            const double x = origin.x + t * direction.x;
            cx = forwardOnly(cx, floorToInt(x) - (direction.x < 0 && x == floorToInt(x) ? 1 : 0),
                             direction.x);
        }
        if (stepY) {
            cy = direction.y > 0 ? by0 + size : by0 - 1;
        } else {
            const double y = origin.y + t * direction.y;
            cy = forwardOnly(cy, floorToInt(y) - (direction.y < 0 && y == floorToInt(y) ? 1 : 0),
                             direction.y);
        }
        if (cx < 0 || cy < 0 || cx >= width_ || cy >= height_) {
            leftCanvas = true;
            break;
        }
    }
    flushRun();

    RaySegment out;
    for (int c = 0; c < 3; ++c) {
        if (leftCanvas && addBoundary) radiance[c] += transmittance[c] * boundary_[c];
        out.radiance[c] = radiance[c];
        out.transmittance[c] = transmittance[c];
    }
    return out;
}

}  // namespace luxel::gi2d
