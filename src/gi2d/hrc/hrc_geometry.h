// Geometry of one HRC frustum in its canonical +x frame
// (docs/algorithms/holographic-radiance-cascades.md §2; Freeman, Sannikov, Margel, "Holographic
// Radiance Cascades for 2D Global Illumination", arXiv:2505.02041).
//
// Cascade n: probe planes x = p * 2^n (pixel borders), one probe per row y (at y + 0.5), rays
// k = 0 .. 2^n with end-point offsets v_n(k) = (2^n, 2k - 2^n), cones i = 0 .. 2^n - 1 between rays
// i and i + 1. Edge rays are exactly +-45 degrees.
#pragma once

#include <cmath>
#include <cstdint>

namespace luxel::gi2d::hrc {

inline constexpr int pow2(int n) {
    return 1 << n;
}

// Offset of ray k of cascade n along the rows (the x offset is 2^n); hrcRayOffsetY in the shared
// kernels, constexpr here for the tables built at compile time.
inline constexpr int rayOffsetY(int n, int k) {
    return 2 * k - pow2(n);
}

// Angle of ray k of cascade n from the frustum axis (paper Eq 13).
inline double rayAngle(int n, int k) {
    return std::atan2(static_cast<double>(rayOffsetY(n, k)), static_cast<double>(pow2(n)));
}

// Angular width of cone j of cascade m: the weight carried by a level-(m-1) ray next to it.
inline double coneWidth(int m, int j) {
    return rayAngle(m, j + 1) - rayAngle(m, j);
}

// Cascades needed so that 2^count planes cover `length` pixels along the axis (at least 1).
inline int cascadeCount(int length) {
    int n = 1;
    while (pow2(n) < length) ++n;
    return n;
}

// Probe planes of cascade n that start inside a frame `length` pixels long: x = p 2^n < length.
inline int planeCount(int length, int n) {
    return (length + pow2(n) - 1) >> n;
}

}  // namespace luxel::gi2d::hrc
