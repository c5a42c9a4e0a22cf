// Sample positions inside a pixel for anti-aliasing, both backends (render_image.cpp on the CPU,
// voxel_render.comp.glsl's main on the GPU): stratified and deterministic per pixel, so images
// do not depend on threads, tiles or the backend.
//
// n = g^2 samples: a jittered g x g grid (one sample per cell). Other n: N-rooks (Shirley 1991):
// column k and row (k * m + shift) mod n of an n x n grid, jittered in the cell; m is the first
// number coprime with n from 0.618 n up (a rank-1 lattice close to the Fibonacci lattice, so the
// rows do not line up on a diagonal) and shift a per-pixel hash. One sample: the pixel centre.
#ifndef LUXEL_GPU_SHARED_PIXEL_SAMPLES_H
#define LUXEL_GPU_SHARED_PIXEL_SAMPLES_H

#include "glsl_compat.h"
#include "voxel_shading.h"

// Most samples per pixel a render accepts.
#define LUXEL_MAX_SAMPLES_PER_PIXEL 256

LUXEL_SHARED_BEGIN

// A hashed number in [0, 1) for pixel (px, py), sample k, dimension `dim`.
LUXEL_FUNC float pixelSampleHash(uint px, uint py, uint k, uint dim) {
    uint h = voxelMixHash(px * 0x9e3779b9u ^ 0x68bc21ebu);
    h = voxelMixHash(h ^ py);
    h = voxelMixHash(h ^ (k * 2u + dim));
    return float(h >> 8u) / float(1 << 24);
}

// The lattice multiplier for n samples: coprime with n, near n / golden ratio.
LUXEL_FUNC int pixelSampleMultiplier(int n) {
    for (int m = max(int(0.618034f * float(n)), 1); m < n; ++m) {
        int a = m, b = n;
        while (b != 0) {
            const int t = a % b;
            a = b;
            b = t;
        }
        if (a == 1) return m;
    }
    return 1;
}

// Offset of sample k (of n) inside pixel (px, py), in [0, 1)^2 from its top-left corner.
LUXEL_FUNC vec2 pixelSampleOffset(uint px, uint py, int k, int n) {
    if (n <= 1) return vec2(0.5f, 0.5f);
    const int g = int(sqrt(float(n)) + 0.5f);
    const uint uk = uint(k);
    const float jx = pixelSampleHash(px, py, uk, 0u);
    const float jy = pixelSampleHash(px, py, uk, 1u);
    if (g * g == n) {
        return vec2((float(k % g) + jx) / float(g), (float(k / g) + jy) / float(g));
    }
    const int shift = int(pixelSampleHash(px, py, 0u, 2u) * float(n));
    const int row = (k * pixelSampleMultiplier(n) + shift) % n;  // a permutation of 0..n-1
    return vec2((float(k) + jx) / float(n), (float(row) + jy) / float(n));
}

LUXEL_SHARED_END

#endif
