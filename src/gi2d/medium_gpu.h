// The 2D medium as the GPU passes read it: one MediumTexel per pixel, rows top to bottom
// (src/gpu/shaders/shared/medium_layout.h).
#pragma once

#include <vector>

#include "gpu/shaders/shared/medium_layout.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d {

// `transposed`: column-major instead (x * height + y), for passes whose threads walk columns.
inline std::vector<gpu::shared::MediumTexel> packMediumForGpu(const Medium2D& medium,
                                                              bool transposed = false) {
    std::vector<gpu::shared::MediumTexel> out(static_cast<std::size_t>(medium.width()) *
                                              medium.height());
    for (int y = 0; y < medium.height(); ++y) {
        for (int x = 0; x < medium.width(); ++x) {
            const Rgb s = medium.absorption.rgb(x, y), e = medium.emission.rgb(x, y);
            const std::size_t i = transposed ? static_cast<std::size_t>(x) * medium.height() + y
                                             : static_cast<std::size_t>(y) * medium.width() + x;
            out[i] = {s.r, s.g, s.b, e.r, e.g, e.b};
        }
    }
    return out;
}

}  // namespace luxel::gi2d
