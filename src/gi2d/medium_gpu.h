// The 2D medium as the GPU passes read it: one MediumTexel per pixel, rows top to bottom
// (src/gpu/shaders/shared/medium_layout.h).
#pragma once

#include <span>
#include <vector>

#include "gpu/shaders/shared/medium_layout.h"
#include "luxel/core/check.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d {

// Packs the medium into `out` (width * height texels), rows in parallel. `transposed`:
// column-major instead (x * height + y), for passes whose threads walk columns.
inline void packMediumForGpu(const Medium2D& medium, std::span<gpu::shared::MediumTexel> out,
                             bool transposed = false) {
    const int width = medium.width(), height = medium.height();
    LUXEL_CHECK_EQ(out.size(), static_cast<std::size_t>(width) * height);
    parallelForRange(height, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                const Rgb s = medium.absorption.rgb(x, y), e = medium.emission.rgb(x, y);
                const std::size_t i = transposed ? static_cast<std::size_t>(x) * height + y
                                                 : static_cast<std::size_t>(y) * width + x;
                out[i] = {s.r, s.g, s.b, e.r, e.g, e.b};
            }
        }
    });
}

inline std::vector<gpu::shared::MediumTexel> packMediumForGpu(const Medium2D& medium,
                                                              bool transposed = false) {
    std::vector<gpu::shared::MediumTexel> out(static_cast<std::size_t>(medium.width()) *
                                              medium.height());
    packMediumForGpu(medium, out, transposed);
    return out;
}

}  // namespace luxel::gi2d
