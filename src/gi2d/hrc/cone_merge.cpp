// HRC cone merge with exact angular weights and the odd/even plane rule.
#include "gi2d/hrc/cone_merge.h"

#include "gi2d/hrc/hrc_geometry.h"
#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {

void ConeBuffer::reset(int planes, int cones, int rows) {
    planes_ = planes;
    cones_ = cones;
    rows_ = rows;
    stride_ = gpu::shared::hrcConeRowHalves(static_cast<std::uint32_t>(rows));
    // Padding rows stay zero, as hrc_merge writes them.
    data_.assign(static_cast<std::size_t>(planes) * cones * 3 * stride_, 0);
}

std::uint64_t ConeBuffer::bytesFor(int planes, int cones, int rows) {
    return static_cast<std::uint64_t>(planes) * cones * 3 *
           gpu::shared::hrcConeRowHalves(static_cast<std::uint32_t>(rows)) * sizeof(std::uint16_t);
}

std::vector<float> coneWeights(int level) {
    std::vector<float> w(pow2(level + 1));
    for (int j = 0; j < pow2(level + 1); ++j) w[j] = static_cast<float>(coneWidth(level + 1, j));
    return w;
}

void mergeCascade(const RayTables& tables, int n, const ConeBuffer* upper, Rgb sky,
                  ConeBuffer& out) {
    const int cones = pow2(n), rows = tables.rows();
    out.reset(tables.planes(n), cones, rows);
    const std::vector<float> weight = coneWeights(n);
    // Fluence of cone j at an upper probe; outside the frame (or above the top cascade) the sky.
    auto upperFluence = [&](int p, int y, int j) -> gpu::shared::vec3 {
        if (upper != nullptr && upper->inRange(p, y)) return toVec3(upper->at(p, j, y));
        return toVec3(sky * weight[j]);
    };
    // Row y blended with row y + second (§5.1); row y alone from cascade 2 up.
    const float secondWeight = gpu::shared::hrcSecondRowWeight(n);
    auto upperRows = [&](int p, int y, int second, int j) -> gpu::shared::vec3 {
        if (secondWeight == 0.0f) return upperFluence(p, y, j);
        return upperFluence(p, y, j) * (1.0f - secondWeight) +
               upperFluence(p, y + second, j) * secondWeight;
    };
    parallelForRange(out.planes() * cones, 1, [&](int begin, int end) {
        // Per-thread scratch: the two rays' table rows here and on the next plane.
        thread_local DecodedRow here[2], next[2];
        for (int index = begin; index < end; ++index) {
            const int p = index / cones, i = index % cones;
            const bool odd = p % 2 == 1;
            for (int s = 0; s < 2; ++s) {
                here[s].load(tables, n, p, i + s);
                if (!odd) next[s].load(tables, n, p + 1, i + s);
            }
            for (int y = 0; y < rows; ++y) {
                gpu::shared::vec3 sum(0.0f);
                for (int s = 0; s < 2; ++s) {
                    const int k = i + s, j = 2 * i + s, dy = gpu::shared::hrcRayOffsetY(n, k);
                    const int axis = gpu::shared::hrcTowardsAxis(s);
                    const float w = weight[j];
                    if (odd) {
                        // The ray ends exactly on upper plane (p + 1) / 2 (Eq 14).
                        sum += gpu::shared::hrcMergeOdd(here[s].at(y), w,
                                                        upperRows((p + 1) / 2, y + dy, axis, j));
                    } else {
                        // Upper plane p / 2 is here: merge near, and far with a double-length
                        // ray to upper plane p / 2 + 1, then average (Eq 15-17).
                        sum += gpu::shared::hrcMergeEven(upperRows(p / 2, y, dy, j),
                                                         over(here[s].at(y), next[s].at(y + dy)), w,
                                                         upperRows(p / 2 + 1, y + 2 * dy, axis, j));
                    }
                }
                out.set(p, i, y, toRgb(sum));
            }
        }
    });
}

}  // namespace luxel::gi2d::hrc
