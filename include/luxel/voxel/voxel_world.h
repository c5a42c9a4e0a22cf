// A dense voxel world stored in cubic chunks: 32-bit RGBA per voxel (alpha > 0 = solid), chunks of
// `chunkSize`^3 voxels laid out one after another so any voxel is found in O(1), plus a solid
// count per chunk and a 64-bit occupancy mask per 4^3 brick so traversal can skip empty space and
// test voxels without touching their colours. Coordinates: x right, y up, z forward;
// voxel (i, j, k) covers [i, i+1] x [j, j+1] x [k, k+1].
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"

namespace luxel::voxel {

struct Voxel {
    std::uint8_t r = 0, g = 0, b = 0, a = 0;  // a = 0: empty
    constexpr bool solid() const { return a != 0; }
    constexpr bool operator==(const Voxel&) const = default;
};

// Largest accepted world side, in voxels.
inline constexpr int kMaxWorldSide = 4096;

class VoxelWorld {
  public:
    // An empty world of `size` voxels (each side 1..kMaxWorldSide) in chunks of `chunkSize`
    // (a power of two in 4..128). Fails with a clear message for bad sizes or when the memory
    // estimate (bytesFor) exceeds what the machine has.
    static Result<VoxelWorld> create(Int3 size, int chunkSize = 32);

    // Bytes a world of this size needs (chunks rounded up to whole chunks).
    static std::uint64_t bytesFor(Int3 size, int chunkSize);

    Int3 size() const { return size_; }
    int chunkSize() const { return chunkSize_; }
    Int3 chunkCount() const { return chunks_; }

    bool inside(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < size_.x && y < size_.y && z < size_.z;
    }
    // Outside the world reads as empty.
    Voxel get(int x, int y, int z) const {
        return inside(x, y, z) ? voxels_[index(x, y, z)] : Voxel{};
    }
    bool solid(int x, int y, int z) const { return get(x, y, z).solid(); }
    // Writes inside the world; outside is ignored.
    void set(int x, int y, int z, Voxel v);

    // Solid voxels in chunk (cx, cy, cz); 0 means the traversal may skip the chunk.
    std::uint32_t chunkSolidCount(int cx, int cy, int cz) const {
        return chunkSolid_[(static_cast<std::size_t>(cz) * chunks_.y + cy) * chunks_.x + cx];
    }
    std::uint64_t solidCount() const;

    // Occupancy of brick (bx, by, bz), the kBrickSide^3 voxels from kBrickSide * (bx, by, bz):
    // bit (z * 16 + y * 4 + x) of the mask is set when local voxel (x, y, z) is solid.
    static constexpr int kBrickShift = 2, kBrickSide = 1 << kBrickShift;
    std::uint64_t brickMask(int bx, int by, int bz) const {
        return bricks_[(static_cast<std::size_t>(bz) * brickCount_.y + by) * brickCount_.x + bx];
    }
    static constexpr int brickBit(int x, int y, int z) {
        constexpr int m = kBrickSide - 1;
        return ((z & m) << (2 * kBrickShift)) | ((y & m) << kBrickShift) | (x & m);
    }

    // Directional empty-space reach of brick (bx, by, bz) towards direction octant `octant`
    // (bit a set: the ray moves towards -inf on axis a; clear: +inf or not at all): the side, in
    // bricks, of the largest cube of bricks without a solid voxel that has this brick at a corner
    // and extends from it towards that octant (bricks outside the world count as empty), capped
    // at kMaxBrickReach; 0 for a brick with a solid voxel. A ray in that octant may cross the cube
    // in one exact jump (docs/algorithms/voxel-traversal.md §3).
    // Only meaningful while emptySpaceCurrent(): set() makes the reach stale when a brick gains
    // its first solid voxel (removals only make it conservative; a brick that loses its last
    // solid voxel gets reach 1 in every octant, the brick itself), and refreshEmptySpace()
    // recomputes it. Generators, importers and scene loading refresh when they finish.
    static constexpr int kMaxBrickReach = 255;
    static constexpr int kOctants = 8;
    static constexpr int octantOf(bool negativeX, bool negativeY, bool negativeZ) {
        return (negativeX ? 1 : 0) | (negativeY ? 2 : 0) | (negativeZ ? 4 : 0);
    }
    std::uint8_t brickReach(int octant, int bx, int by, int bz) const {
        return brickReach_[static_cast<std::size_t>(octant) * bricks_.size() +
                           (static_cast<std::size_t>(bz) * brickCount_.y + by) * brickCount_.x +
                           bx];
    }
    bool emptySpaceCurrent() const {
        return !emptySpaceStale_.value.load(std::memory_order_relaxed);
    }
    void refreshEmptySpace();
    Int3 brickCount() const { return brickCount_; }
    // The masks and reach as arrays, brick-linear with x fastest (index (bz * by + y) * bx + x
    // for brickCount() (bx, by, bz)), for traversal loops that gather them for several rays. The
    // reach is 8 such planes of bytes, octant after octant: octant o's at o * (bricks in all).
    const std::uint64_t* brickMaskData() const { return bricks_.data(); }
    const std::uint8_t* brickReachData() const { return brickReach_.data(); }

    // Same size and the same voxel everywhere (the chunk size does not matter).
    bool operator==(const VoxelWorld& other) const;

  private:
    std::size_t index(int x, int y, int z) const {
        const int shift = chunkShift_, mask = chunkSize_ - 1;
        const std::size_t chunk =
            (static_cast<std::size_t>(z >> shift) * chunks_.y + (y >> shift)) * chunks_.x +
            (x >> shift);
        const std::size_t local =
            (static_cast<std::size_t>(z & mask) * chunkSize_ + (y & mask)) * chunkSize_ +
            (x & mask);
        return (chunk << (3 * shift)) + local;
    }

    Int3 size_, chunks_, brickCount_;
    int chunkSize_ = 32, chunkShift_ = 5;
    std::vector<Voxel> voxels_;
    std::vector<std::uint32_t> chunkSolid_;
    // One word per brick (bricks tile chunks), so chunk-parallel writers never share one.
    std::vector<std::uint64_t> bricks_;
    std::vector<std::uint8_t> brickReach_;  // kOctants planes of bricks_.size() bytes
    // Written by concurrent set() calls from chunk-parallel generators, hence atomic; copyable so
    // the world stays a value type.
    struct StaleFlag {
        std::atomic<bool> value{false};
        StaleFlag() = default;
        StaleFlag(const StaleFlag& o) : value(o.value.load()) {}
        StaleFlag& operator=(const StaleFlag& o) {
            value = o.value.load();
            return *this;
        }
    } emptySpaceStale_;
};

}  // namespace luxel::voxel
