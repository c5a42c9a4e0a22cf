// Pieces of the RC solver shared by the CPU and GPU paths.
#pragma once

#include <utility>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::gi2d::rc {

Status validate(const RcOptions& options);

// The mean of options.jitters solves, the r-th with shift rcJitterShift(r) and jitters = 1; one
// plain solve when jitters is 1. `solve` takes those options.
template <typename Solve>
Result<Image> averageJitters(const RcOptions& options, Solve&& solve) {
    if (options.jitters <= 1) return solve(options);
    RcOptions one = options;
    one.jitters = 1;
    Image sum;
    for (int r = 0; r < options.jitters; ++r) {
        rcJitterShift(r, one.jitterX, one.jitterY);
        Result<Image> f = solve(one);
        if (!f) return f;
        if (r == 0) {
            sum = std::move(*f);
            continue;
        }
        for (std::size_t i = 0; i < sum.size(); ++i) sum.data()[i] += f->data()[i];
    }
    const float scale = 1.0f / static_cast<float>(options.jitters);
    for (std::size_t i = 0; i < sum.size(); ++i) sum.data()[i] *= scale;
    return sum;
}

// Values stored per probe of cascade `index`: cascade 0 keeps the mean over all its directions
// (the fluence); higher cascades keep, per direction of the cascade below, the mean of its 4
// children (pre-averaging: the merge only ever needs that mean).
int storedPerProbe(const RcCascade& cascade, int index);

// The image from cascade `level`'s stored values: the fluence bilinearly interpolated to pixel
// centres, or (debug view) the nearest probe's mean over its values.
Image readOut(const RcCascade& cascade, int level, const std::vector<Rgb>& stored, int width,
              int height, bool nearestProbe);

}  // namespace luxel::gi2d::rc
