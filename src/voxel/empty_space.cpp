// Chebyshev (L-infinity) distance transform, separable: the exact distance to the nearest occupied
// brick is min over bricks of max(|dx|, |dy|, |dz|), which factors into a 1D transform along x
// followed by min-max passes along y and z (each pass only looks as far as the best so far).
#include "voxel/empty_space.h"

#include <algorithm>
#include <cstdlib>

#include "luxel/core/parallel.h"

namespace luxel::voxel {
namespace {

// One min-max pass along an axis: out[i] = min over j of max(|i - j|, in[j]), for every line of
// the grid along that axis. `stride` steps along the axis; `lines` enumerates line starts.
void minMaxPass(std::vector<std::uint8_t>& values, int length, std::size_t stride,
                const std::vector<std::size_t>& lineStarts, int cap) {
    parallelForRange(static_cast<int>(lineStarts.size()), 64, [&](int begin, int end) {
        std::vector<std::uint8_t> line(static_cast<std::size_t>(length));
        for (int l = begin; l < end; ++l) {
            const std::size_t start = lineStarts[static_cast<std::size_t>(l)];
            for (int i = 0; i < length; ++i) line[i] = values[start + i * stride];
            for (int i = 0; i < length; ++i) {
                int best = line[i];
                // Any j farther than `best` cannot improve it: max(|i - j|, .) >= |i - j|.
                for (int k = 1; k < best; ++k) {
                    if (i - k >= 0) best = std::min(best, std::max(k, int{line[i - k]}));
                    if (i + k < length) best = std::min(best, std::max(k, int{line[i + k]}));
                }
                values[start + i * stride] = static_cast<std::uint8_t>(std::min(best, cap));
            }
        }
    });
}

}  // namespace

void computeBrickDistances(const std::vector<std::uint64_t>& masks, Int3 count, int cap,
                           std::vector<std::uint8_t>& distances) {
    distances.resize(masks.size());
    const std::size_t sx = 1, sy = static_cast<std::size_t>(count.x),
                      sz = static_cast<std::size_t>(count.x) * count.y;
    for (std::size_t i = 0; i < masks.size(); ++i) {
        distances[i] = masks[i] != 0 ? 0 : static_cast<std::uint8_t>(cap);
    }
    std::vector<std::size_t> starts;
    for (int z = 0; z < count.z; ++z)
        for (int y = 0; y < count.y; ++y) starts.push_back(z * sz + y * sy);
    minMaxPass(distances, count.x, sx, starts, cap);
    starts.clear();
    for (int z = 0; z < count.z; ++z)
        for (int x = 0; x < count.x; ++x) starts.push_back(z * sz + x * sx);
    minMaxPass(distances, count.y, sy, starts, cap);
    starts.clear();
    for (int y = 0; y < count.y; ++y)
        for (int x = 0; x < count.x; ++x) starts.push_back(y * sy + x * sx);
    minMaxPass(distances, count.z, sz, starts, cap);
}

}  // namespace luxel::voxel
