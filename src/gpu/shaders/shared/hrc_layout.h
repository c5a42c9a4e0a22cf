// HRC structures and constants shared by C++ and GLSL (one definition; offsets checked below and
// in tests/gpu/shared_layout_test.cpp).
//
// Ray table T_n in memory (binary16, rows innermost), one entry = 3 words:
//   word 0: L.r | L.g << 16    word 1: L.b | T.r << 16    word 2: T.g | T.b << 16
//   entry index = (p * (2^n + 1) + k) * rows + y
#ifndef LUXEL_GPU_SHARED_HRC_LAYOUT_H
#define LUXEL_GPU_SHARED_HRC_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace luxel::gpu::shared {
using uint = std::uint32_t;
#endif

// Rows per workgroup of the HRC passes.
#define LUXEL_HRC_GROUP_SIZE 64
// 32-bit words per ray-table entry (six binary16 values).
#define LUXEL_HRC_ENTRY_WORDS 3

// Push constants of hrc_extend: builds T_level from T_{level-1}.
struct HrcExtendParams {
    uint level;        // n >= 1
    uint rows;         // frame rows
    uint planesBelow;  // plane count of T_{n-1}
    uint planes;       // plane count of T_n
};

#ifdef __cplusplus
static_assert(sizeof(HrcExtendParams) == 16);
static_assert(offsetof(HrcExtendParams, rows) == 4);
static_assert(offsetof(HrcExtendParams, planesBelow) == 8);
static_assert(offsetof(HrcExtendParams, planes) == 12);
}  // namespace luxel::gpu::shared
#endif

#endif
