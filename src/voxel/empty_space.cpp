// The largest empty cube of bricks with a corner at a brick, per octant, by dynamic programming:
// a cube of side k at brick b towards octant (sx, sy, sz) is b itself plus the cubes of side k - 1
// at the 7 neighbours b + (ix sx, iy sy, iz sz), i in {0, 1}^3 \ {0}, so
// side(b) = 0 for an occupied brick, else 1 + the smallest side of those neighbours (outside the
// grid: empty without end, the cap). One sweep per octant, from the far corner back.
#include "voxel/empty_space.h"

#include <algorithm>
#include <cstddef>

#include "luxel/core/parallel.h"

namespace luxel::voxel {
namespace {

// One octant's plane: `plane[i]` for every brick i, visiting bricks after their neighbours ahead.
void reachTowards(const std::vector<std::uint64_t>& masks, Int3 count, int cap, int octant,
                  std::uint8_t* plane) {
    const int sx = (octant & 1) ? -1 : 1, sy = (octant & 2) ? -1 : 1, sz = (octant & 4) ? -1 : 1;
    const std::size_t rowStride = static_cast<std::size_t>(count.x);
    const std::size_t sliceStride = rowStride * count.y;
    const auto insideAxis = [](int v, int n) { return v >= 0 && v < n; };
    for (int iz = 0; iz < count.z; ++iz) {
        const int z = sz > 0 ? count.z - 1 - iz : iz;
        const bool hasZ = insideAxis(z + sz, count.z);
        for (int iy = 0; iy < count.y; ++iy) {
            const int y = sy > 0 ? count.y - 1 - iy : iy;
            const bool hasY = insideAxis(y + sy, count.y);
            const std::size_t row = z * sliceStride + y * rowStride;
            // The rows ahead (null: outside the grid, empty as far as the cap).
            const std::uint8_t* aheadY =
                hasY ? plane + row + sy * std::ptrdiff_t(rowStride) : nullptr;
            const std::uint8_t* aheadZ =
                hasZ ? plane + row + sz * std::ptrdiff_t(sliceStride) : nullptr;
            const std::uint8_t* aheadYZ = hasY && hasZ
                                              ? plane + row + sy * std::ptrdiff_t(rowStride) +
                                                    sz * std::ptrdiff_t(sliceStride)
                                              : nullptr;
            for (int ix = 0; ix < count.x; ++ix) {
                const int x = sx > 0 ? count.x - 1 - ix : ix;
                if (masks[row + x] != 0) {
                    plane[row + x] = 0;
                    continue;
                }
                const bool hasX = insideAxis(x + sx, count.x);
                const int nx = x + sx;
                int m = cap;
                if (hasX) m = std::min<int>(m, plane[row + nx]);
                if (aheadY) {
                    m = std::min<int>(m, aheadY[x]);
                    if (hasX) m = std::min<int>(m, aheadY[nx]);
                }
                if (aheadZ) {
                    m = std::min<int>(m, aheadZ[x]);
                    if (hasX) m = std::min<int>(m, aheadZ[nx]);
                }
                if (aheadYZ) {
                    m = std::min<int>(m, aheadYZ[x]);
                    if (hasX) m = std::min<int>(m, aheadYZ[nx]);
                }
                plane[row + x] = static_cast<std::uint8_t>(std::min(m + 1, cap));
            }
        }
    }
}

}  // namespace

void computeBrickReach(const std::vector<std::uint64_t>& masks, Int3 count, int cap,
                       std::vector<std::uint8_t>& reach) {
    constexpr int kOctants = 8;
    reach.resize(masks.size() * kOctants);
    parallelForRange(kOctants, 1, [&](int begin, int end) {
        for (int o = begin; o < end; ++o) {
            reachTowards(masks, count, cap, o, reach.data() + o * masks.size());
        }
    });
}

}  // namespace luxel::voxel
