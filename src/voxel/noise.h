// Gradient noise: Perlin's improved noise (Perlin 2002, "Improving Noise", SIGGRAPH) in 2D and 3D
// with a seeded permutation table, and fractal Brownian motion (sum of octaves) on top.
#pragma once

#include <array>
#include <cstdint>

namespace luxel::voxel {

class GradientNoise {
  public:
    // The permutation table is a Fisher-Yates shuffle driven by Pcg32(seed): same seed, same noise.
    explicit GradientNoise(std::uint64_t seed);

    // Values in about [-1, 1], 0 at integer lattice points; smooth (C2 fade curve).
    float noise2(float x, float y) const;
    float noise3(float x, float y, float z) const;

    // Fractal Brownian motion: sum over `octaves` of gain^i * noise(p * lacunarity^i), divided by
    // the sum of the amplitudes so the result stays in about [-1, 1].
    float fbm2(float x, float y, int octaves, float lacunarity, float gain) const;
    float fbm3(float x, float y, float z, int octaves, float lacunarity, float gain) const;

  private:
    int hash(int i) const { return perm_[i & 511]; }
    std::array<std::uint16_t, 512> perm_{};  // 256 shuffled entries, repeated to skip a modulo
};

}  // namespace luxel::voxel
