// A dense 8-bit volume: one opacity byte per voxel (0 empty .. 255 opaque) and, optionally, one
// RGBA colour per voxel. The input the octree builder, the OpenVDB importer and the generators
// share; x right, y up, z forward, index (z * sy + y) * sx + x.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/octree/octree.h"

namespace luxel::octree {

// Largest dense volume side accepted (a 4096^3 volume is 64 GiB: sparse scenes are built from
// procedural sources instead, octree_build.h).
inline constexpr int kMaxVolumeSide = 4096;

class Volume {
  public:
    // Fails for sides outside 1..kMaxVolumeSide or when the bytes exceed the available memory.
    static Result<Volume> create(Int3 size, bool withColours = false);
    static std::uint64_t bytesFor(Int3 size, bool withColours);

    Int3 size() const { return size_; }
    bool hasColours() const { return !colours_.empty(); }
    bool inside(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < size_.x && y < size_.y && z < size_.z;
    }
    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * size_.y + y) * size_.x + x;
    }
    std::uint8_t opacity(int x, int y, int z) const {
        return inside(x, y, z) ? opacity_[index(x, y, z)] : 0;
    }
    Colour colour(int x, int y, int z) const {
        return inside(x, y, z) && hasColours() ? colours_[index(x, y, z)] : Colour{};
    }
    void set(int x, int y, int z, std::uint8_t opacity, Colour colour = {}) {
        if (!inside(x, y, z)) return;
        opacity_[index(x, y, z)] = opacity;
        if (hasColours()) colours_[index(x, y, z)] = colour;
    }
    const std::vector<std::uint8_t>& opacities() const { return opacity_; }
    std::uint64_t nonZeroCount() const;

  private:
    Int3 size_;
    std::vector<std::uint8_t> opacity_;
    std::vector<Colour> colours_;
};

}  // namespace luxel::octree
