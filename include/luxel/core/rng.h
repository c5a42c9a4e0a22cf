// Deterministic random numbers: PCG32 (O'Neill 2014) seeded from a hash of (seed, x, y), so every
// pixel gets its own stream whatever thread computes it.
#pragma once

#include <cstdint>

namespace luxel {

// SplitMix64 finaliser (Steele et al. 2014): a strong 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

constexpr std::uint64_t hashSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0) {
    return mix64(mix64(mix64(seed) ^ a) ^ (b * 0x632be59bd9b4e019ull));
}

class Pcg32 {
  public:
    explicit constexpr Pcg32(std::uint64_t seed, std::uint64_t stream = 0x5851f42d4c957f2dull)
        : state_(0), inc_((stream << 1u) | 1u) {
        next();
        state_ += seed;
        next();
    }

    constexpr std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1), 24 bits so the float never rounds up to 1.
    constexpr float nextFloat() { return static_cast<float>(next() >> 8) * 0x1p-24f; }
    // Uniform in [0, 1), 32 bits.
    constexpr double nextDouble() { return static_cast<double>(next()) * 0x1p-32; }

  private:
    std::uint64_t state_, inc_;
};

}  // namespace luxel
