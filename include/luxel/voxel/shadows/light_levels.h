// Block-game sky light: a breadth-first flood fill of light levels 0..15 through empty voxels.
// Level 15 fills every empty voxel of a column open to the sky (above its highest solid voxel),
// and each 6-connected step through empty voxels costs one level. The baseline the other shadow
// methods are compared with: cheap, soft, and blind to the sun's direction.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

class LightLevels {
  public:
    static constexpr int kMaxLevel = 15;

    static LightLevels build(const VoxelWorld& world);

    Int3 size() const { return size_; }
    // Level of a voxel (0 inside solids); outside the world: kMaxLevel (open sky).
    int level(int x, int y, int z) const;
    // One byte per voxel, x fastest, then y, then z.
    const std::vector<std::uint8_t>& levels() const { return levels_; }

  private:
    Int3 size_;
    std::vector<std::uint8_t> levels_;
};

}  // namespace luxel::voxel
