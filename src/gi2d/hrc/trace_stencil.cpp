#include "gi2d/hrc/trace_stencil.h"

#include <algorithm>
#include <cmath>

#include "gi2d/hrc/hrc_geometry.h"

namespace luxel::gi2d::hrc {

std::vector<StencilStep> traceStencil(int level, int k) {
    const double dx = pow2(level), dy = rayOffsetY(level, k);
    const double length = std::hypot(dx, dy);
    // Ray parameters (0..1) where the segment crosses a pixel border along either axis.
    std::vector<double> cuts{0.0, 1.0};
    for (int u = 1; u < pow2(level); ++u) cuts.push_back(u / dx);
    if (dy != 0.0) {
        const double y0 = 0.5, y1 = 0.5 + dy;
        for (int v = static_cast<int>(std::ceil(std::min(y0, y1)));
             v <= static_cast<int>(std::floor(std::max(y0, y1))); ++v) {
            cuts.push_back((v - y0) / dy);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    std::vector<StencilStep> steps;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = cuts[i], b = cuts[i + 1];
        if (b - a <= 1e-12) continue;  // a corner: both borders at once
        const double mid = 0.5 * (a + b);
        steps.push_back({static_cast<int>(std::floor(mid * dx)),
                         static_cast<int>(std::floor(0.5 + mid * dy)),
                         static_cast<float>((b - a) * length)});
    }
    return steps;
}

}  // namespace luxel::gi2d::hrc
