// The four HRC frustums (+x, +y, -x, -y) as frames in which the frustum looks along +x
// (docs/algorithms/holographic-radiance-cascades.md §6.1). The +-y frames are reflections across
// the diagonal rather than rotations; the per-frustum algorithm is symmetric under y -> -y, so this
// changes nothing.
#pragma once

#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::hrc {

enum class Frustum { PlusX = 0, PlusY = 1, MinusX = 2, MinusY = 3 };

struct FrustumFrame {
    Frustum frustum;
    int canvasWidth, canvasHeight;
    int length;  // frame pixels along the axis
    int rows;    // frame pixels across it

    // Canvas pixel shown at frame pixel (u, v); the GPU's trace pass maps its reads the same way.
    void toCanvas(int u, int v, int& x, int& y) const {
        const gpu::shared::ivec2 c = gpu::shared::hrcFrameToCanvas(
            static_cast<unsigned>(frustum), gpu::shared::ivec2(u, v), canvasWidth, canvasHeight);
        x = c.x, y = c.y;
    }
};

FrustumFrame makeFrame(Frustum frustum, int canvasWidth, int canvasHeight);

// The medium resampled into the frame (no boundary radiance: the solver injects it itself).
Medium2D frameMedium(const Medium2D& medium, const FrustumFrame& frame);

}  // namespace luxel::gi2d::hrc
