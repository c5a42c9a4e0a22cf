// Exact DDA ray integration through the 2D medium with uniform-block skipping.
#include "luxel/gi2d/ray_march.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "luxel/core/check.h"

namespace luxel::gi2d {

namespace {
constexpr int kMaxBlockLevel = 12;
}

RayMarcher::RayMarcher(const Medium2D& medium)
    : width_(medium.width()), height_(medium.height()), boundary_(medium.boundaryRadiance) {
    cells_.resize(static_cast<std::size_t>(width_) * height_);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const Rgb s = medium.absorption.rgb(x, y), e = medium.emission.rgb(x, y);
            cells_[static_cast<std::size_t>(y) * width_ + x] = {{s.r, s.g, s.b}, {e.r, e.g, e.b}};
        }
    }
    buildBlockLevels();
}

std::uint64_t RayMarcher::bytesFor(std::uint64_t width, std::uint64_t height) {
    return width * height * (sizeof(Cell) + 1);
}

void RayMarcher::buildBlockLevels() {
    blockLevel_.assign(cells_.size(), 0);
    // uniform[k] marks aligned blocks of side 2^k (inside the canvas) whose cells are identical;
    // a block is uniform when its 4 children are and their first cells are equal.
    std::vector<std::uint8_t> previous(cells_.size(), 1), current;
    int prevW = width_, prevH = height_;
    for (int k = 1; k <= kMaxBlockLevel; ++k) {
        const int w = width_ >> k, h = height_ >> k;
        if (w == 0 || h == 0) break;
        current.assign(static_cast<std::size_t>(w) * h, 0);
        bool any = false;
        for (int by = 0; by < h; ++by) {
            for (int bx = 0; bx < w; ++bx) {
                auto child = [&](int i, int j) {
                    return previous[static_cast<std::size_t>(2 * by + j) * prevW + 2 * bx + i];
                };
                if (!(child(0, 0) && child(1, 0) && child(0, 1) && child(1, 1))) continue;
                const int half = 1 << (k - 1);
                auto cellAt = [&](int i, int j) -> const Cell& {
                    return cells_[static_cast<std::size_t>((by << k) + j * half) * width_ +
                                  (bx << k) + i * half];
                };
                const Cell& first = cellAt(0, 0);
                if (!(first == cellAt(1, 0) && first == cellAt(0, 1) && first == cellAt(1, 1))) {
                    continue;
                }
                current[static_cast<std::size_t>(by) * w + bx] = 1;
                any = true;
                for (int y = by << k; y < (by + 1) << k; ++y) {
                    std::fill_n(&blockLevel_[static_cast<std::size_t>(y) * width_ + (bx << k)],
                                1 << k, static_cast<std::uint8_t>(k));
                }
            }
        }
        if (!any) break;
        previous.swap(current);
        prevW = w;
        prevH = h;
    }
    (void)prevH;
}

RaySegment RayMarcher::march(Vec2d origin, Vec2d direction, double maxDistance,
                             float cutoff) const {
    LUXEL_DCHECK(std::abs(length(direction) - 1.0) < 1e-6);
    LUXEL_DCHECK(origin.x >= 0 && origin.y >= 0 && origin.x <= width_ && origin.y <= height_);

    const double inf = std::numeric_limits<double>::infinity();
    const double invX = direction.x != 0.0 ? 1.0 / direction.x : inf;
    const double invY = direction.y != 0.0 ? 1.0 / direction.y : inf;
    int cx = std::min(static_cast<int>(std::floor(origin.x)), width_ - 1);
    int cy = std::min(static_cast<int>(std::floor(origin.y)), height_ - 1);

    float radiance[3] = {0, 0, 0};
    float transmittance[3] = {1, 1, 1};
    // The pending run of identical cells and its total length.
    const Cell* run = nullptr;
    double runLength = 0.0;
    auto flushRun = [&] {
        if (run == nullptr || runLength <= 0.0) return;
        for (int c = 0; c < 3; ++c) {
            if (run->sigma[c] == 0.0f) continue;  // vacuum: t = 1 and nothing emitted
            const float t = std::exp(-run->sigma[c] * static_cast<float>(runLength));
            radiance[c] += transmittance[c] * run->emission[c] * (1.0f - t);
            transmittance[c] *= t;
        }
    };

    double t = 0.0;
    bool leftCanvas = false;
    while (true) {
        const std::size_t index = static_cast<std::size_t>(cy) * width_ + cx;
        const int k = blockLevel_[index];
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
        const Cell* cell = &cells_[index];
        if (run == nullptr || !(*run == *cell)) {
            flushRun();
            if (std::max(transmittance[0], std::max(transmittance[1], transmittance[2])) < cutoff) {
                run = nullptr;
                break;
            }
            run = cell;
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
            cx = static_cast<int>(std::floor(x));
            if (direction.x < 0 && x == cx) --cx;
        }
        if (stepY) {
            cy = direction.y > 0 ? by0 + size : by0 - 1;
        } else {
            const double y = origin.y + t * direction.y;
            cy = static_cast<int>(std::floor(y));
            if (direction.y < 0 && y == cy) --cy;
        }
        if (cx < 0 || cy < 0 || cx >= width_ || cy >= height_) {
            leftCanvas = true;
            break;
        }
    }
    flushRun();

    RaySegment out;
    for (int c = 0; c < 3; ++c) {
        if (leftCanvas) radiance[c] += transmittance[c] * boundary_[c];
        out.radiance[c] = radiance[c];
        out.transmittance[c] = transmittance[c];
    }
    return out;
}

}  // namespace luxel::gi2d
