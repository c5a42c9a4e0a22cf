// The four HRC frustums (+x, +y, -x, -y) as frames in which the frustum looks along +x
// (docs/algorithms/holographic-radiance-cascades.md §6.1). The +-y frames are reflections across
// the diagonal rather than rotations; the per-frustum algorithm is symmetric under y -> -y, so this
// changes nothing.
#pragma once

#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

enum class Frustum { PlusX = 0, PlusY = 1, MinusX = 2, MinusY = 3 };

struct FrustumFrame {
    Frustum frustum;
    int canvasWidth, canvasHeight;
    int length;  // frame pixels along the axis
    int rows;    // frame pixels across it

    // Canvas pixel shown at frame pixel (u, v).
    void toCanvas(int u, int v, int& x, int& y) const {
        switch (frustum) {
            case Frustum::PlusX:
                x = u, y = v;
                break;
            case Frustum::MinusX:
                x = canvasWidth - 1 - u, y = v;
                break;
            case Frustum::PlusY:
                x = v, y = u;
                break;
            default:
                x = v, y = canvasHeight - 1 - u;
                break;  // MinusY
        }
    }
};

FrustumFrame makeFrame(Frustum frustum, int canvasWidth, int canvasHeight);

// The medium resampled into the frame (no boundary radiance: the solver injects it itself).
Medium2D frameMedium(const Medium2D& medium, const FrustumFrame& frame);

}  // namespace luxel::gi2d::hrc
