// A random volumetric 2D medium for the pass parity tests: partly transparent emitting pixels
// everywhere, a few opaque walls, and a sky, so every pass sees partial transmittance, emission
// and out-of-frame reads.
#pragma once

#include <cstdint>

#include "luxel/core/rng.h"
#include "luxel/gi2d/medium2d.h"

namespace luxel::gi2d::testing {

inline Medium2D randomMedium(int w, int h, std::uint64_t seed, Rgb sky) {
    Medium2D m{Image(w, h, 3), Image(w, h, 3), sky};
    Pcg32 rng(seed);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const bool wall = rng.nextFloat() < 0.05f;
            m.absorption.setRgb(
                x, y,
                wall ? Rgb(50.0f) : Rgb(rng.nextFloat() * 0.5f, rng.nextFloat() * 0.1f, 0.2f));
            m.emission.setRgb(x, y, Rgb(rng.nextFloat() * 3.0f, rng.nextFloat(), 0.5f));
        }
    }
    return m;
}

}  // namespace luxel::gi2d::testing
