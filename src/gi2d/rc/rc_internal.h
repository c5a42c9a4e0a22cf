// Pieces of the RC solver shared by the CPU and GPU paths.
#pragma once

#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::gi2d::rc {

Status validate(const RcOptions& options);

// Values stored per probe of cascade `index`: cascade 0 keeps the mean over all its directions
// (the fluence); higher cascades keep, per direction of the cascade below, the mean of its 4
// children (pre-averaging: the merge only ever needs that mean).
int storedPerProbe(const RcCascade& cascade, int index);

// The image from cascade `level`'s stored values: the fluence bilinearly interpolated to pixel
// centres, or (debug view) the nearest probe's mean over its values.
Image readOut(const RcCascade& cascade, int level, const std::vector<Rgb>& stored, int width,
              int height, bool nearestProbe);

}  // namespace luxel::gi2d::rc
