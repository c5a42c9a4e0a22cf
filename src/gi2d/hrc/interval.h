// A radiance interval (docs/algorithms/holographic-radiance-cascades.md §1): radiance L delivered
// towards the start and transmittance T, composited front to back ("over", paper Eq 8). The one
// definition is the shared C++/GLSL header src/gpu/shaders/shared/hrc_kernels.h.
#pragma once

#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/vec.h"

namespace luxel::gi2d::hrc {

using Interval = gpu::shared::HrcInterval;

inline Interval emptyInterval() {
    return gpu::shared::hrcEmptyInterval();
}

inline Interval over(const Interval& near, const Interval& far) {
    return gpu::shared::hrcOver(near, far);
}

inline Interval average(const Interval& a, const Interval& b) {
    return gpu::shared::hrcAverage(a, b);
}

inline gpu::shared::vec3 toVec3(Rgb c) {
    return {c.r, c.g, c.b};
}

inline Rgb toRgb(gpu::shared::vec3 v) {
    return {v.x, v.y, v.z};
}

}  // namespace luxel::gi2d::hrc
