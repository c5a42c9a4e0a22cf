// The 2D medium as GPU shaders read it: six floats per pixel, sigma rgb then emission rgb
// (src/gpu/shaders/shared/hrc_layout.h, rc_layout.h).
#pragma once

#include <vector>

#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d {

inline std::vector<float> packMediumForGpu(const Medium2D& medium) {
    std::vector<float> out(static_cast<std::size_t>(medium.width()) * medium.height() * 6);
    for (int y = 0; y < medium.height(); ++y) {
        for (int x = 0; x < medium.width(); ++x) {
            float* e = &out[(static_cast<std::size_t>(y) * medium.width() + x) * 6];
            const Rgb s = medium.absorption.rgb(x, y), em = medium.emission.rgb(x, y);
            e[0] = s.r, e[1] = s.g, e[2] = s.b, e[3] = em.r, e[4] = em.g, e[5] = em.b;
        }
    }
    return out;
}

}  // namespace luxel::gi2d
