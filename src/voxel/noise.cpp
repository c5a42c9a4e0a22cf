// Improved Perlin noise (Perlin 2002) and fBm, deterministic by seed.
#include "noise.h"

#include <cmath>
#include <utility>

#include "luxel/core/rng.h"

namespace luxel::voxel {
namespace {

// 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at 0 and 1 (Perlin 2002).
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
float lerp(float t, float a, float b) {
    return a + t * (b - a);
}

// Lattice cell index mod 256 without a float-to-int conversion that could overflow (far octaves).
int wrap256(float cellFloor) {
    const double m =
        static_cast<double>(cellFloor) - 256.0 * std::floor(static_cast<double>(cellFloor) / 256.0);
    return static_cast<int>(m) & 255;
}

// The 12 cube-edge gradients of Perlin 2002 (16 entries, 4 repeated, to index with 4 bits).
float grad3(int h, float x, float y, float z) {
    h &= 15;
    const float u = h < 8 ? x : y;
    const float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// 8 gradients in 2D: the axes and diagonals.
float grad2(int h, float x, float y) {
    switch (h & 7) {
        case 0:
            return x + y;
        case 1:
            return -x + y;
        case 2:
            return x - y;
        case 3:
            return -x - y;
        case 4:
            return x;
        case 5:
            return -x;
        case 6:
            return y;
        default:
            return -y;
    }
}

}  // namespace

GradientNoise::GradientNoise(std::uint64_t seed) {
    std::array<std::uint16_t, 256> p{};
    for (int i = 0; i < 256; ++i) p[i] = static_cast<std::uint16_t>(i);
    Pcg32 rng(seed);
    for (int i = 255; i > 0; --i) {
        // Bounded by rejection so every permutation is equally likely.
        const std::uint32_t bound = static_cast<std::uint32_t>(i + 1);
        const std::uint32_t threshold = (0u - bound) % bound;
        std::uint32_t r = rng.next();
        while (r < threshold) r = rng.next();
        const int j = static_cast<int>(r % bound);
        std::swap(p[i], p[j]);
    }
    for (int i = 0; i < 512; ++i) perm_[i] = p[i & 255];
}

float GradientNoise::noise2(float x, float y) const {
    const float fx = std::floor(x), fy = std::floor(y);
    if (!std::isfinite(fx) || !std::isfinite(fy)) return 0.0f;
    const int xi = wrap256(fx), yi = wrap256(fy);
    x -= fx;
    y -= fy;
    const float u = fade(x), v = fade(y);
    const int a = hash(xi) + yi, b = hash(xi + 1) + yi;
    // At most 1 in magnitude: the diagonal gradients can each contribute 1 at a cell centre.
    return lerp(v, lerp(u, grad2(hash(a), x, y), grad2(hash(b), x - 1, y)),
                lerp(u, grad2(hash(a + 1), x, y - 1), grad2(hash(b + 1), x - 1, y - 1)));
}

float GradientNoise::noise3(float x, float y, float z) const {
    const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    if (!std::isfinite(fx) || !std::isfinite(fy) || !std::isfinite(fz)) return 0.0f;
    const int xi = wrap256(fx), yi = wrap256(fy), zi = wrap256(fz);
    x -= fx;
    y -= fy;
    z -= fz;
    const float u = fade(x), v = fade(y), w = fade(z);
    const int a = hash(xi) + yi, aa = hash(a) + zi, ab = hash(a + 1) + zi;
    const int b = hash(xi + 1) + yi, ba = hash(b) + zi, bb = hash(b + 1) + zi;
    return lerp(
        w,
        lerp(v, lerp(u, grad3(hash(aa), x, y, z), grad3(hash(ba), x - 1, y, z)),
             lerp(u, grad3(hash(ab), x, y - 1, z), grad3(hash(bb), x - 1, y - 1, z))),
        lerp(v, lerp(u, grad3(hash(aa + 1), x, y, z - 1), grad3(hash(ba + 1), x - 1, y, z - 1)),
             lerp(u, grad3(hash(ab + 1), x, y - 1, z - 1),
                  grad3(hash(bb + 1), x - 1, y - 1, z - 1))));
}

float GradientNoise::fbm2(float x, float y, int octaves, float lacunarity, float gain) const {
    float sum = 0, amplitude = 1, norm = 0, f = 1;
    for (int i = 0; i < octaves; ++i) {
        // Each octave is shifted so the lattice zeros of the octaves do not line up at the origin.
        sum += amplitude * noise2(x * f + 17.3f * i, y * f + 31.7f * i);
        norm += amplitude;
        amplitude *= gain;
        f *= lacunarity;
    }
    return norm > 0 ? sum / norm : 0.0f;
}

float GradientNoise::fbm3(float x, float y, float z, int octaves, float lacunarity,
                          float gain) const {
    float sum = 0, amplitude = 1, norm = 0, f = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * noise3(x * f + 17.3f * i, y * f + 31.7f * i, z * f + 47.9f * i);
        norm += amplitude;
        amplitude *= gain;
        f *= lacunarity;
    }
    return norm > 0 ? sum / norm : 0.0f;
}

}  // namespace luxel::voxel
