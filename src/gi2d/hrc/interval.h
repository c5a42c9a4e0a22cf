// A radiance interval (docs/algorithms/holographic-radiance-cascades.md §1): radiance L delivered
// towards the start and transmittance T, composited front to back ("over", paper Eq 8).
#pragma once

#include "luxel/core/vec.h"

namespace luxel::gi2d::hrc {

struct Interval {
    Rgb radiance;
    Rgb transmittance{1.0f, 1.0f, 1.0f};
};

inline Interval over(const Interval& near, const Interval& far) {
    return {near.radiance + near.transmittance * far.radiance,
            near.transmittance * far.transmittance};
}

inline Interval average(const Interval& a, const Interval& b) {
    return {(a.radiance + b.radiance) * 0.5f, (a.transmittance + b.transmittance) * 0.5f};
}

}  // namespace luxel::gi2d::hrc
