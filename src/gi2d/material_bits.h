// The bit pattern of one pixel's material (sigma rgb, E rgb) as a hash key: the palettes of
// distinct materials that RayMarcher and the RC stencil pass build from a medium.
#pragma once

#include <cstddef>
#include <cstdint>

namespace luxel::gi2d {

struct MaterialBits {
    std::uint32_t words[6];
    bool operator==(const MaterialBits&) const = default;
};

struct MaterialBitsHash {
    std::size_t operator()(const MaterialBits& m) const {
        std::uint64_t h = 0x9e3779b97f4a7c15ull;
        for (std::uint32_t w : m.words) h = (h ^ w) * 0x100000001b3ull;
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

}  // namespace luxel::gi2d
