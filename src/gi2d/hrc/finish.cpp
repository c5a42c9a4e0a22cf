#include "gi2d/hrc/finish.h"

#include "gpu/shaders/shared/hrc_kernels.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {
namespace {

namespace shared = gpu::shared;

shared::vec3 toVec(Rgb c) {
    return {c.r, c.g, c.b};
}

}  // namespace

Image finishFluence(const Medium2D& medium, const Image& beyond, int frustums, bool blur) {
    const int w = beyond.width(), h = beyond.height();
    auto opacity = [&](int x, int y) {
        return shared::hrcOpacity(toVec(medium.absorption.rgb(x, y)));
    };
    Image out(w, h, 3);
    parallelForRange(h, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                Rgb arriving = beyond.rgb(x, y);
                if (blur) {
                    const float centre = opacity(x, y);
                    Rgb sum = arriving * 4.0f;
                    float weight = 4.0f;
                    const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
                    for (int t = 0; t < 4; ++t) {
                        if (!beyond.inside(nx[t], ny[t])) continue;
                        if (!shared::hrcBlurTakes(centre, opacity(nx[t], ny[t]))) continue;
                        sum += beyond.rgb(nx[t], ny[t]);
                        weight += 1.0f;
                    }
                    arriving = sum * (1.0f / weight);
                }
                const shared::vec3 f = shared::hrcFinishPixel(
                    toVec(medium.absorption.rgb(x, y)), toVec(medium.emission.rgb(x, y)),
                    toVec(arriving), static_cast<float>(frustums));
                out.setRgb(x, y, {f.x, f.y, f.z});
            }
        }
    });
    return out;
}

}  // namespace luxel::gi2d::hrc
