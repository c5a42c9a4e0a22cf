// HRC ray tables: exact base intervals and O(1) ray extension.
#include "gi2d/hrc/ray_tables.h"

#include <algorithm>
#include <cmath>

#include "gi2d/hrc/hrc_geometry.h"
#include "gpu/shaders/shared/hrc_kernels.h"
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

void RayTables::decodeRow(int n, int p, int k, std::vector<float>& out) const {
    out.resize(static_cast<std::size_t>(rows_) * 6);
    if (p < 0 || p >= planes_[n]) {
        for (int y = 0; y < rows_; ++y) {
            float* e = &out[static_cast<std::size_t>(y) * 6];
            e[0] = e[1] = e[2] = 0.0f;
            e[3] = e[4] = e[5] = 1.0f;
        }
        return;
    }
    const Entry* row = &tables_[n][index(n, p, k, 0)];
    static_assert(sizeof(Entry) == 6 * sizeof(std::uint16_t));
    halvesToFloats(row[0].radiance, out.data(), out.size());
}

void RayTables::encodeRow(int n, int p, int k, const std::vector<float>& in) {
    Entry* row = &tables_[n][index(n, p, k, 0)];
    floatsToHalves(in.data(), row[0].radiance, static_cast<std::size_t>(rows_) * 6);
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

void traceLevel(RayTables& tables, const RayMarcher& marcher, int n, float depthScale) {
    forEachPlaneAndRay(tables, n, [&](int p, int k) {
        const double dx = pow2(n), dy = rayOffsetY(n, k);
        const double len = std::hypot(dx, dy);
        const Vec2d direction{dx / len, dy / len};
        const double x = static_cast<double>(p) * pow2(n);
        for (int y = 0; y < tables.rows(); ++y) {
            const RaySegment s = marcher.march({x, y + 0.5}, direction, len, 0.0f, depthScale);
            tables.set(n, p, y, k, {toVec3(s.radiance), toVec3(s.transmittance)});
        }
    });
}

void traceBaseLevels(RayTables& tables, const RayMarcher& marcher, int tracedLevels) {
    const int levels = std::min(tracedLevels, tables.levels());
    for (int n = 0; n < levels; ++n) {
        traceLevel(tables, marcher, n, gpu::shared::hrcTracedDepthScale(n, tracedLevels));
    }
}

void extendLevels(RayTables& tables, int tracedLevels) {
    for (int n = std::max(tracedLevels, 1); n < tables.levels(); ++n) extendLevel(tables, n);
}

void extendLevel(RayTables& tables, int n) {
    const int rows = tables.rows();
    forEachPlaneAndRay(tables, n, [&](int p, int k) {
        // Per-thread scratch rows, decoded once per (plane, ray) pair.
        thread_local DecodedRow nearLo, farHi, nearHi, farLo;
        thread_local std::vector<float> out;
        out.resize(static_cast<std::size_t>(rows) * 6);
        const int lo = k >> 1, hi = (k + 1) >> 1;
        const int dyLo = gpu::shared::hrcRayOffsetY(n - 1, lo),
                  dyHi = gpu::shared::hrcRayOffsetY(n - 1, hi);
        nearLo.load(tables, n - 1, 2 * p, lo);
        farHi.load(tables, n - 1, 2 * p + 1, hi);
        if (lo != hi) {
            nearHi.load(tables, n - 1, 2 * p, hi);
            farLo.load(tables, n - 1, 2 * p + 1, lo);
        }
        for (int y = 0; y < rows; ++y) {
            Interval v = over(nearLo.at(y), farHi.at(y + dyLo));
            // Even k: both paths are the straight ray. Odd k: average the two bent paths.
            if (lo != hi) v = average(v, over(nearHi.at(y), farLo.at(y + dyHi)));
            float* e = &out[static_cast<std::size_t>(y) * 6];
            for (int c = 0; c < 3; ++c) {
                e[c] = v.radiance[c];
                e[3 + c] = v.transmittance[c];
            }
        }
        tables.encodeRow(n, p, k, out);
    });
}

}  // namespace luxel::gi2d::hrc
