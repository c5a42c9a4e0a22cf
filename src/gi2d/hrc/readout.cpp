#include "gi2d/hrc/readout.h"

#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {

void readOut(const FrustumFrame& frame, const ConeBuffer& cones, int level, Rgb sky,
             Image& beyondSum) {
    parallelForRange(frame.rows, 8, [&](int begin, int end) {
        for (int v = begin; v < end; ++v) {
            for (int u = 0; u < frame.length; ++u) {
                int x, y;
                frame.toCanvas(u, v, x, y);
                const int plane = gpu::shared::hrcReadoutPlane(u, level);
                Rgb beyond;
                if (cones.inRange(plane, v)) {
                    for (int i = 0; i < cones.cones(); ++i) beyond += cones.at(plane, i, v);
                } else {
                    beyond = sky * LUXEL_HRC_QUARTER_TURN;
                }
                beyondSum.setRgb(x, y, beyondSum.rgb(x, y) + beyond);
            }
        }
    });
}

}  // namespace luxel::gi2d::hrc
