// Bulk binary16 conversion with run-time dispatch to F16C (vcvtph2ps / vcvtps2ph).
#include "luxel/core/half.h"

#include <immintrin.h>

#if defined(__clang__)
#include <cpuid.h>
#endif

namespace luxel {
namespace {

[[gnu::target("f16c,avx")]] void halvesToFloatsF16c(const std::uint16_t* in, float* out,
                                                    std::size_t count) {
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8) {
        const __m128i h = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + i));
        _mm256_storeu_ps(out + i, _mm256_cvtph_ps(h));
    }
    for (; i < count; ++i) out[i] = _cvtsh_ss(in[i]);
}

[[gnu::target("f16c,avx")]] void floatsToHalvesF16c(const float* in, std::uint16_t* out,
                                                    std::size_t count) {
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8) {
        const __m128i h = _mm256_cvtps_ph(_mm256_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), h);
    }
    for (; i < count; ++i) out[i] = static_cast<std::uint16_t>(_cvtss_sh(in[i], 0));
}

#if defined(__clang__)
// clang (16) has no "f16c" name for __builtin_cpu_supports: CPUID leaf 1 holds both feature
// bits, and XGETBV says whether the OS saves the AVX registers.
const bool kF16c = [] {
    unsigned a = 0, b = 0, c = 0, d = 0;
    if (__get_cpuid(1, &a, &b, &c, &d) == 0) return false;
    if ((c & bit_F16C) == 0 || (c & bit_AVX) == 0 || (c & bit_OSXSAVE) == 0) return false;
    unsigned lo = 0, hi = 0;
    __asm__("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
    return (lo & 6u) == 6u;  // XMM and YMM state enabled
}();
#else
const bool kF16c = [] {
    __builtin_cpu_init();  // static initialisers may run before libgcc's own
    return __builtin_cpu_supports("f16c") && __builtin_cpu_supports("avx");
}();
#endif

}  // namespace

bool hasHardwareHalfConversion() {
    return kF16c;
}

void halvesToFloats(const std::uint16_t* in, float* out, std::size_t count) {
    if (kF16c) return halvesToFloatsF16c(in, out, count);
    for (std::size_t i = 0; i < count; ++i) out[i] = halfToFloat(in[i]);
}

void floatsToHalves(const float* in, std::uint16_t* out, std::size_t count) {
    if (kF16c) return floatsToHalvesF16c(in, out, count);
    for (std::size_t i = 0; i < count; ++i) out[i] = floatToHalf(in[i]);
}

}  // namespace luxel
