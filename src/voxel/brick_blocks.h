// Empty halves of a non-empty 4^3 brick, read from its 64-bit occupancy mask (bit
// z * 16 + y * 4 + x): the 4x2x4, 2x4x4 and 4x4x2 halves. The SIMD walk (castRayBatch,
// occludedBatch) crosses an empty half in one box jump where the per-voxel loop visits its cells
// one by one, and counts those visits, so `steps` stays the per-voxel loop's
// (docs/algorithms/voxel-traversal.md §4.2). Also any box of a brick's cells, for the slab walks of
// tiles and beams (§4.6, §4.7). No storage of its own: the masks are the world's.
#pragma once

#include <cstdint>

namespace luxel::voxel::blocks {

// The cells of a brick in the lower (index 0) or upper (index 1) half along each axis.
inline constexpr std::uint64_t kHalfX[2] = {0x3333333333333333ull, 0xCCCCCCCCCCCCCCCCull};
inline constexpr std::uint64_t kHalfY[2] = {0x00FF00FF00FF00FFull, 0xFF00FF00FF00FF00ull};
inline constexpr std::uint64_t kHalfZ[2] = {0x00000000FFFFFFFFull, 0xFFFFFFFF00000000ull};

// Most cells a walk visits in one half (4 + 2 + 4 - 2, e.g. 1 + 3 + 1 + 3 cells): a jump over a
// half adds at most this many visits to `steps`.
inline constexpr int kMaxVisits = 8;

// The cells [lo, hi] of a brick on each axis (local coordinates 0..3, inclusive): the bits of a
// mask that test them all with one AND.
inline std::uint64_t boxBits(const int lo[3], const int hi[3]) {
    const std::uint64_t row = ((2u << hi[0]) - 1u) & ~((1u << lo[0]) - 1u);
    std::uint64_t layer = 0;
    for (int y = lo[1]; y <= hi[1]; ++y) layer |= row << (4 * y);
    std::uint64_t box = 0;
    for (int z = lo[2]; z <= hi[2]; ++z) box |= layer << (16 * z);
    return box;
}

}  // namespace luxel::voxel::blocks
