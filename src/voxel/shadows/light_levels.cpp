// Sky light by breadth-first search: every source starts at the top level, so the queue holds
// levels in non-increasing order and each voxel is set once, to its final level.
#include "luxel/voxel/shadows/light_levels.h"

#include <vector>

namespace luxel::voxel {

LightLevels LightLevels::build(const VoxelWorld& world) {
    LightLevels l;
    l.size_ = world.size();
    const Int3 s = l.size_;
    l.levels_.assign(static_cast<std::size_t>(s.x) * s.y * s.z, 0);
    auto index = [&](int x, int y, int z) {
        return (static_cast<std::size_t>(z) * s.y + y) * s.x + x;
    };
    std::vector<Int3> queue;
    for (int z = 0; z < s.z; ++z) {
        for (int x = 0; x < s.x; ++x) {
            for (int y = s.y - 1; y >= 0 && !world.solid(x, y, z); --y) {
                l.levels_[index(x, y, z)] = kMaxLevel;
                queue.push_back({x, y, z});
            }
        }
    }
    static constexpr int kSteps[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                         {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const Int3 c = queue[head];
        const int next = l.levels_[index(c.x, c.y, c.z)] - 1;
        if (next <= 0) continue;
        for (const auto& d : kSteps) {
            const int x = c.x + d[0], y = c.y + d[1], z = c.z + d[2];
            if (!world.inside(x, y, z) || world.solid(x, y, z)) continue;
            std::uint8_t& v = l.levels_[index(x, y, z)];
            if (v >= next) continue;
            v = static_cast<std::uint8_t>(next);
            queue.push_back({x, y, z});
        }
    }
    return l;
}

int LightLevels::level(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= size_.x || y >= size_.y || z >= size_.z) return kMaxLevel;
    return levels_[(static_cast<std::size_t>(z) * size_.y + y) * size_.x + x];
}

}  // namespace luxel::voxel
