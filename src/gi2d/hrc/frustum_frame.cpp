// Frame mapping for the four HRC frustums.
#include "gi2d/hrc/frustum_frame.h"

#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {

FrustumFrame makeFrame(Frustum frustum, int canvasWidth, int canvasHeight) {
    const bool alongX = frustum == Frustum::PlusX || frustum == Frustum::MinusX;
    return {frustum, canvasWidth, canvasHeight, alongX ? canvasWidth : canvasHeight,
            alongX ? canvasHeight : canvasWidth};
}

Medium2D frameMedium(const Medium2D& medium, const FrustumFrame& frame) {
    Medium2D out{Image(frame.length, frame.rows, 3), Image(frame.length, frame.rows, 3), Rgb()};
    parallelForRange(frame.rows, 16, [&](int begin, int end) {
        for (int v = begin; v < end; ++v) {
            for (int u = 0; u < frame.length; ++u) {
                int x, y;
                frame.toCanvas(u, v, x, y);
                out.emission.setRgb(u, v, medium.emission.rgb(x, y));
                out.absorption.setRgb(u, v, medium.absorption.rgb(x, y));
            }
        }
    });
    return out;
}

}  // namespace luxel::gi2d::hrc
