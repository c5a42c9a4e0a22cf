// IEEE 754 binary16 storage for large tables: conversions to and from float, round to nearest
// even, with subnormals, infinities and NaN. Arithmetic is always done in float.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace luxel {

inline std::uint16_t floatToHalf(float value) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    const std::uint32_t sign = (bits >> 16) & 0x8000u;
    const std::uint32_t absBits = bits & 0x7fffffffu;
    if (absBits >= 0x7f800000u) {  // inf or NaN
        return static_cast<std::uint16_t>(sign | 0x7c00u | (absBits > 0x7f800000u ? 0x200u : 0u));
    }
    if (absBits >= 0x477ff000u) return static_cast<std::uint16_t>(sign | 0x7c00u);  // overflow
    if (absBits < 0x38800000u) {
        // Subnormal half (or zero): add a magic number so the FPU does the rounding.
        const float magic = std::bit_cast<float>(0x3f000000u);  // 0.5: shifts mantissa into place
        const float shifted = std::bit_cast<float>(absBits) + magic;
        return static_cast<std::uint16_t>(
            sign | (std::bit_cast<std::uint32_t>(shifted) - std::bit_cast<std::uint32_t>(magic)));
    }
    // Normal: rebias the exponent and round the 13 dropped mantissa bits to nearest even.
    const std::uint32_t mantissaOdd = (absBits >> 13) & 1u;
    const std::uint32_t rounded = absBits + 0xc8000fffu + mantissaOdd;  // -(127-15)<<23 + bias
    return static_cast<std::uint16_t>(sign | (rounded >> 13));
}

inline float halfToFloat(std::uint16_t half) {
    const std::uint32_t sign = static_cast<std::uint32_t>(half & 0x8000u) << 16;
    const std::uint32_t exponent = (half >> 10) & 0x1fu;
    const std::uint32_t mantissa = half & 0x3ffu;
    if (exponent == 0x1fu) return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));
    if (exponent == 0) {
        // Subnormal or zero: value = mantissa * 2^-24.
        const float magnitude = static_cast<float>(mantissa) * 0x1p-24f;
        return sign ? -magnitude : magnitude;
    }
    return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

}  // namespace luxel

namespace luxel {

// Bulk conversions for table rows. They use the CPU's F16C instructions when it has them
// (checked once at run time) and the functions above otherwise; both round the same way.
void halvesToFloats(const std::uint16_t* in, float* out, std::size_t count);
void floatsToHalves(const float* in, std::uint16_t* out, std::size_t count);

// Whether the bulk conversions run on F16C (for benchmarks and notes).
bool hasHardwareHalfConversion();

}  // namespace luxel
