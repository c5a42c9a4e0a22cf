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

void mergeCascade(const RayTables& tables, int n, const ConeBuffer* upper, Rgb sky, ConeBuffer& out,
                  const MergeNearLights& nearLights) {
    const int cones = pow2(n), rows = tables.rows();
    out.reset(tables.planes(n), cones, rows);
    const std::vector<float> weight = coneWeights(n);
    // Fluence of cone j at an upper probe; outside the frame (or above the top cascade) the sky.
    auto upperFluence = [&](int p, int y, int j) -> gpu::shared::vec3 {
        if (upper != nullptr && upper->inRange(p, y)) return toVec3(upper->at(p, j, y));
        return toVec3(sky * weight[j]);
    };
    // The rows each read blends (§5.1): towards the cone's bisector, and the near probe's row
    // along the side's ray.
    const float second = gpu::shared::hrcSecondRowWeight(n);
    // Plane p is read out for pixel p - 1 (§6.2); plane 0 for none (it never reaches the image).
    auto nearWeight = [&](int p, int y) {
        if (nearLights.mask == nullptr || p < 1) return gpu::shared::hrcNearRowWeight(n);
        int x = 0, v = 0;
        nearLights.frame.toCanvas(p - 1, y, x, v);
        return gpu::shared::hrcNearRowWeightAt(n, nearLights.mask->at(x, v));
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
                const float nearSecond = odd ? 0.0f : nearWeight(p, y);
                for (int s = 0; s < 2; ++s) {
                    const int k = i + s, j = 2 * i + s, dy = gpu::shared::hrcRayOffsetY(n, k);
                    const int axis = gpu::shared::hrcTowardsAxis(s);
                    const float w = weight[j];
                    if (odd) {
                        // The ray ends exactly on upper plane (p + 1) / 2 (Eq 14).
                        const int q = (p + 1) / 2, e = y + dy;
                        sum += gpu::shared::hrcMergeOdd(
                            here[s].at(y), w,
                            gpu::shared::hrcBlendTwoRows(upperFluence(q, e, j),
                                                         upperFluence(q, e + axis, j), second));
                    } else {
                        // Upper plane p / 2 is here: merge near, and far with a double-length
                        // ray to upper plane p / 2 + 1, then average (Eq 15-17).
                        const int q = p / 2, e = y + 2 * dy;
                        const gpu::shared::vec3 near =
                            nearSecond == 0.0f ? upperFluence(q, y, j)
                                               : gpu::shared::hrcBlendTwoRows(
                                                     upperFluence(q, y, j),
                                                     upperFluence(q, y + dy, j), nearSecond);
                        const gpu::shared::vec3 far = gpu::shared::hrcBlendThreeRows(
                            upperFluence(q + 1, e, j), upperFluence(q + 1, e + axis, j),
                            upperFluence(q + 1, e + 2 * axis, j), second);
                        sum += gpu::shared::hrcMergeEven(
                            near, over(here[s].at(y), next[s].at(y + dy)), w, far);
                    }
                }
                out.set(p, i, y, toRgb(sum));
            }
        }
    });
}

}  // namespace luxel::gi2d::hrc
