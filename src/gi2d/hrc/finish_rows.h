// One row of HRC's finish (finish.h, docs/algorithms/holographic-radiance-cascades.md §6.2, §7)
// with Highway vectors: the cross blur's gated sum (paper Eq 21), then the pixel's own half-pixel
// segment in front (hrcFinishPixelThrough). The vectors make the same float operations in the
// same order as one pixel at a time, so the same bits.
#pragma once

namespace luxel::gi2d::hrc {

struct FinishRow {
    const float* current = nullptr;  // the row's light beyond, RGB (a copy: out may be the row)
    // The rows above and below as the blur reads them, or null where there is none; their gates
    // (hrcOpacity) and the row's own: blur only.
    const float* above = nullptr;
    const float* below = nullptr;
    const float* opacityAbove = nullptr;
    const float* opacityHere = nullptr;
    const float* opacityBelow = nullptr;
    const float* transmittance = nullptr;  // hrcFinishTransmittance per pixel, RGB
    const float* emission = nullptr;
    int width = 0;
    float frustums = 4;
    bool blur = true;
};

// out[3 x + c] for every pixel of the row.
void finishRow(const FinishRow& row, float* out);

// The same for pixels [x0, x1), one at a time: the vectors' ends and their reference.
void finishPixels(const FinishRow& row, int x0, int x1, float* out);

}  // namespace luxel::gi2d::hrc
