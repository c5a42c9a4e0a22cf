// The voxel path tracer's random numbers (include/luxel/voxel/path_trace_rng.h) in 32-bit words,
// so the GPU draws exactly the CPU's numbers without 64-bit integers (shaderInt64 is optional in
// Vulkan): a 64-bit value is a uvec2 (low word, high word), and SplitMix64's finaliser is written
// with 32-bit adds, shifts, xors and multiplies (the high half of a 32 x 32 product from 16-bit
// halves). Compiled as C++ (tests/voxel/path_trace_gpu_test.cpp checks it against PathRng bit for
// bit) and as GLSL (path_trace.comp.glsl).
#ifndef LUXEL_GPU_SHARED_PATH_RNG_H
#define LUXEL_GPU_SHARED_PATH_RNG_H

#include "glsl_compat.h"

LUXEL_SHARED_BEGIN

// The high 32 bits of a * b.
LUXEL_FUNC uint pathMulHigh(uint a, uint b) {
    const uint a0 = a & 0xffffu, a1 = a >> 16u, b0 = b & 0xffffu, b1 = b >> 16u;
    const uint low = a0 * b0;
    const uint middle1 = a1 * b0 + (low >> 16u);  // < 2^32: no carry lost
    const uint middle2 = a0 * b1 + (middle1 & 0xffffu);
    return a1 * b1 + (middle1 >> 16u) + (middle2 >> 16u);
}

// Low 64 bits of a * b.
LUXEL_FUNC uvec2 pathMul64(uvec2 a, uvec2 b) {
    return uvec2(a.x * b.x, pathMulHigh(a.x, b.x) + a.x * b.y + a.y * b.x);
}

LUXEL_FUNC uvec2 pathAdd64(uvec2 a, uvec2 b) {
    const uint low = a.x + b.x;
    return uvec2(low, a.y + b.y + (low < a.x ? 1u : 0u));
}

// z ^ (z >> s) for 0 < s < 32.
LUXEL_FUNC uvec2 pathXorShift64(uvec2 z, uint s) {
    return uvec2(z.x ^ ((z.x >> s) | (z.y << (32u - s))), z.y ^ (z.y >> s));
}

// The 64-bit golden ratio 0x9e3779b97f4a7c15 (SplitMix64's increment).
LUXEL_FUNC uvec2 pathGolden() {
    return uvec2(0x7f4a7c15u, 0x9e3779b9u);
}

// PathRng::mix: SplitMix64's finaliser of z + golden.
LUXEL_FUNC uvec2 pathMix64(uvec2 z) {
    z = pathAdd64(z, pathGolden());
    z = pathMul64(pathXorShift64(z, 30u), uvec2(0x1ce4e5b9u, 0xbf58476du));
    z = pathMul64(pathXorShift64(z, 27u), uvec2(0x133111ebu, 0x94d049bbu));
    return pathXorShift64(z, 31u);
}

// PathRng's state for (seed, pixel, sample): mix(mix(mix(seed) + pixel) + sample).
LUXEL_FUNC uvec2 pathRngKey(uvec2 seed, uint pixel, uint sampleIndex) {
    const uvec2 a = pathMix64(seed);
    const uvec2 b = pathMix64(pathAdd64(a, uvec2(pixel, 0u)));
    return pathMix64(pathAdd64(b, uvec2(sampleIndex, 0u)));
}

// PathRng::next: uniform in [0, 1) from the top 24 bits of the next number.
LUXEL_FUNC float pathRngNext(LUXEL_INOUT(uvec2) state) {
    state = pathAdd64(state, pathGolden());
    return float(pathMix64(state).y >> 8u) * 5.9604644775390625e-8f;  // 2^-24
}

LUXEL_SHARED_END

#endif
