// The path tracer's random numbers: counter-based, so a sample's numbers depend only on (seed,
// pixel, sample) and never on which thread or pass draws them. The key hashes the three with the
// SplitMix64 finaliser; the n-th number is that finaliser applied to key + n * golden ratio (the
// SplitMix64 generator started at the key).
#pragma once

#include <cstdint>

namespace luxel::voxel {

class PathRng {
  public:
    PathRng(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample)
        : state_(mix(mix(mix(seed) + pixel) + sample)) {}

    // Uniform in [0, 1): the top 24 bits of the next 64-bit number.
    float next() {
        state_ += kGolden;
        return static_cast<float>(mix(state_) >> 40) * 0x1p-24f;
    }

    static constexpr std::uint64_t mix(std::uint64_t z) {
        z += kGolden;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }

  private:
    static constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ull;
    std::uint64_t state_;
};

}  // namespace luxel::voxel
