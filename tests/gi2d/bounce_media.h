// Small media for the bounce tests, built pixel by pixel (no rasteriser involved).
#pragma once

#include "luxel/core/metrics.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d::test {

// Relative L1 of `a` against the reference `b` (compareImages).
inline double relativeL1(const Image& a, const Image& b) {
    return compareImages(a, b).value().relativeL1;
}

// An empty n x n medium with scattering and reflectance images (all zero).
inline Medium2D emptyBounceMedium(int n) {
    Medium2D m{Image(n, n, 3), Image(n, n, 3), Rgb()};
    m.scattering = Image(n, n, 3);
    m.reflectance = Image(n, n, 3);
    return m;
}

// Fills [x0, x1) x [y0, y1) with one material.
inline void fillRect(Medium2D& m, int x0, int y0, int x1, int y1, Rgb emission, Rgb sigma,
                     Rgb scattering = {}, Rgb reflectance = {}) {
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            m.emission.setRgb(x, y, emission);
            m.absorption.setRgb(x, y, sigma);
            m.scattering.setRgb(x, y, scattering);
            m.reflectance.setRgb(x, y, reflectance);
        }
    }
}

// A closed opaque square ring `thickness` pixels thick along the canvas border.
inline void fillRing(Medium2D& m, int thickness, Rgb emission, Rgb reflectance) {
    const int n = m.width();
    const Rgb opaque(kMaxAbsorption);
    fillRect(m, 0, 0, n, thickness, emission, opaque, {}, reflectance);
    fillRect(m, 0, n - thickness, n, n, emission, opaque, {}, reflectance);
    fillRect(m, 0, 0, thickness, n, emission, opaque, {}, reflectance);
    fillRect(m, n - thickness, 0, n, n, emission, opaque, {}, reflectance);
}

// Fog (albedo 0.7, sigma 0.06 / px) lit by a bright opaque block, with a black wall casting a
// shadow; open to the outside.
inline Medium2D fogScene(int n = 64) {
    Medium2D m = emptyBounceMedium(n);
    fillRect(m, 0, 0, n, n, {}, Rgb(0.06f), Rgb(0.7f));
    fillRect(m, n / 8, n / 2 - 4, n / 8 + 6, n / 2 + 4, Rgb(4.0f, 3.0f, 1.5f), Rgb(kMaxAbsorption));
    fillRect(m, n / 2, n / 4, n / 2 + 2, n * 3 / 4, {}, Rgb(kMaxAbsorption));
    return m;
}

// A closed room with reflective walls (0.6), a light in one corner, a partition with a gap.
inline Medium2D reflectiveRoom(int n = 64) {
    Medium2D m = emptyBounceMedium(n);
    fillRing(m, 3, {}, Rgb(0.6f, 0.5f, 0.4f));
    fillRect(m, 6, 6, 12, 12, Rgb(5.0f), Rgb(kMaxAbsorption));
    fillRect(m, n / 2, 3, n / 2 + 2, n * 2 / 3, {}, Rgb(kMaxAbsorption), {}, Rgb(0.6f));
    return m;
}

}  // namespace luxel::gi2d::test
