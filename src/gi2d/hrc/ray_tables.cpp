// HRC ray tables: exact base intervals and O(1) ray extension.
#include "gi2d/hrc/ray_tables.h"

#include <algorithm>
#include <cmath>

#include "gi2d/hrc/hrc_geometry.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {

void RayTables::reset(int length, int rows, int levels) {
    levels_ = levels;
    rows_ = rows;
    planes_.resize(levels);
    tables_.resize(std::max<std::size_t>(tables_.size(), levels));
    for (int n = 0; n < levels; ++n) {
        planes_[n] = planeCount(length, n);
        tables_[n].resize(static_cast<std::size_t>(planes_[n]) * (pow2(n) + 1) * rows);
    }
}

std::uint64_t RayTables::bytesFor(int length, int rows, int levels) {
    std::uint64_t entries = 0;
    for (int n = 0; n < levels; ++n) {
        entries += static_cast<std::uint64_t>(planeCount(length, n)) * (pow2(n) + 1) * rows;
    }
    return entries * sizeof(Entry);
}

namespace {

// Calls body(p, k) for every (plane, ray) pair of cascade n, in parallel.
template <typename Body>
void forEachPlaneAndRay(const RayTables& tables, int n, Body&& body) {
    const int rays = pow2(n) + 1;
    parallelForRange(tables.planes(n) * rays, 1, [&](int begin, int end) {
        for (int index = begin; index < end; ++index) body(index / rays, index % rays);
    });
}

}  // namespace

void traceBaseLevels(RayTables& tables, const RayMarcher& marcher, int tracedLevels) {
    const int levels = std::min(tracedLevels, tables.levels());
    for (int n = 0; n < levels; ++n) {
        forEachPlaneAndRay(tables, n, [&](int p, int k) {
            const double dx = pow2(n), dy = rayOffsetY(n, k);
            const double len = std::hypot(dx, dy);
            const Vec2d direction{dx / len, dy / len};
            const double x = static_cast<double>(p) * pow2(n);
            for (int y = 0; y < tables.rows(); ++y) {
                const RaySegment s = marcher.march({x, y + 0.5}, direction, len, 0.0f);
                tables.set(n, p, y, k, {s.radiance, s.transmittance});
            }
        });
    }
}

void extendLevels(RayTables& tables, int tracedLevels) {
    for (int n = std::max(tracedLevels, 1); n < tables.levels(); ++n) {
        const int h = pow2(n - 1);
        forEachPlaneAndRay(tables, n, [&](int p, int k) {
            const int lo = k >> 1, hi = (k + 1) >> 1;
            const int dyLo = 2 * lo - h, dyHi = 2 * hi - h;
            for (int y = 0; y < tables.rows(); ++y) {
                const Interval a = over(tables.get(n - 1, 2 * p, y, lo),
                                        tables.get(n - 1, 2 * p + 1, y + dyLo, hi));
                if (lo == hi) {  // even k: both paths are the straight ray
                    tables.set(n, p, y, k, a);
                    continue;
                }
                const Interval b = over(tables.get(n - 1, 2 * p, y, hi),
                                        tables.get(n - 1, 2 * p + 1, y + dyHi, lo));
                tables.set(n, p, y, k, average(a, b));
            }
        });
    }
}

}  // namespace luxel::gi2d::hrc
