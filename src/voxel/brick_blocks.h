// Empty sub-blocks of a non-empty 4^3 brick, read from its 64-bit occupancy mask (bit
// z * 16 + y * 4 + x): the halves (4x2x4 and the like), quarter columns (2x2x4) and octants (2^3)
// of the brick. The CPU walks cross an empty sub-block in one box jump where the per-voxel loop
// visits its cells one by one, and count those visits, so `steps` stays the per-voxel loop's
// (docs/algorithms/voxel-traversal.md §4.2). No storage of its own: the masks are the world's.
#pragma once

#include <cstdint>

namespace luxel::voxel::blocks {

// The cells of a brick in the lower (index 0) or upper (index 1) half along each axis.
inline constexpr std::uint64_t kHalfX[2] = {0x3333333333333333ull, 0xCCCCCCCCCCCCCCCCull};
inline constexpr std::uint64_t kHalfY[2] = {0x00FF00FF00FF00FFull, 0xFF00FF00FF00FF00ull};
inline constexpr std::uint64_t kHalfZ[2] = {0x00000000FFFFFFFFull, 0xFFFFFFFF00000000ull};

// Most cells a walk visits in one sub-block (a 4x2x4 half: 1 + 3 + 1 + 3): a jump over a
// sub-block adds at most this many visits to `steps`.
inline constexpr int kMaxVisits = 8;

// Which axes the largest empty sub-block holding local cell (x, y, z) (each 0..3) halves: bit a
// set = that axis spans 2 cells, clear = all 4. -1 when even the cell's octant holds a solid
// voxel. The halves come first (y, x, z: ground and walls are mostly horizontal or vertical
// layers), then the quarter columns, then the octant. `mask` is non-zero.
inline int emptySubBlock(std::uint64_t mask, int x, int y, int z) {
    const std::uint64_t hx = kHalfX[(x >> 1) & 1], hy = kHalfY[(y >> 1) & 1],
                        hz = kHalfZ[(z >> 1) & 1];
    if ((mask & hx & hy & hz) != 0) return -1;
    if ((mask & hy) == 0) return 2;
    if ((mask & hx) == 0) return 1;
    if ((mask & hz) == 0) return 4;
    if ((mask & hx & hy) == 0) return 1 | 2;
    if ((mask & hy & hz) == 0) return 2 | 4;
    if ((mask & hx & hz) == 0) return 1 | 4;
    return 1 | 2 | 4;
}

// The sub-block's cells along one axis: [lo, hi] for global cell c, clipped to the world side n.
inline void subBlockRange(int c, bool halved, int n, int& lo, int& hi) {
    lo = c & (halved ? ~1 : ~3);
    hi = lo + (halved ? 1 : 3);
    if (hi > n - 1) hi = n - 1;
}

}  // namespace luxel::voxel::blocks
