// The cells a traced HRC ray crosses, once per (cascade, ray) instead of once per probe
// (docs/algorithms/holographic-radiance-cascades.md §3, §7.1). Every probe of a plane starts at
// (x, y + 0.5) with whole-pixel x and y, so the rays of one (cascade, ray) pair are translates of
// each other by whole pixels: they cross the same cells with the same lengths. The list is the
// exact one the DDA of RayMarcher visits (corner crossings give no zero-length cell).
#pragma once

#include <vector>

namespace luxel::gi2d::hrc {

struct StencilStep {
    int du = 0, dv = 0;   // cell offset from (x, y): along the frustum axis and across it
    float length = 0.0f;  // pixels of the ray inside that cell
};

// Cells, front to back, of the segment from (0, 0.5) to (2^level, 0.5 + 2k - 2^level).
std::vector<StencilStep> traceStencil(int level, int k);

}  // namespace luxel::gi2d::hrc
