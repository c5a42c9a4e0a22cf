// Chunked dense voxel storage.
#include "luxel/voxel/voxel_world.h"

#include <bit>
#include <numeric>
#include <string>

#include "luxel/core/memory.h"
#include "voxel/empty_space.h"

namespace luxel::voxel {

std::uint64_t VoxelWorld::bytesFor(Int3 size, int chunkSize) {
    std::uint64_t chunks = 1;
    for (int a = 0; a < 3; ++a)
        chunks *= static_cast<std::uint64_t>((size[a] + chunkSize - 1) / chunkSize);
    const std::uint64_t perChunk = static_cast<std::uint64_t>(chunkSize) * chunkSize * chunkSize;
    // Bricks tile every chunk (chunk sides are powers of two >= 4), 64 voxels per mask word, and
    // one reach byte per octant.
    return chunks * (perChunk * sizeof(Voxel) + sizeof(std::uint32_t) +
                     perChunk / 64 * (sizeof(std::uint64_t) + kOctants * sizeof(std::uint8_t)));
}

Result<VoxelWorld> VoxelWorld::create(Int3 size, int chunkSize) {
    for (int a = 0; a < 3; ++a) {
        if (size[a] < 1 || size[a] > kMaxWorldSide) {
            return Error("world size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                         "x" + std::to_string(size.z) + " is invalid: each side must be in 1.." +
                         std::to_string(kMaxWorldSide));
        }
    }
    if (chunkSize < 4 || chunkSize > 128 ||
        !std::has_single_bit(static_cast<unsigned>(chunkSize))) {
        return Error("chunk size must be a power of two in 4..128, got " +
                     std::to_string(chunkSize));
    }
    const std::string what = "a " + std::to_string(size.x) + "x" + std::to_string(size.y) + "x" +
                             std::to_string(size.z) + " voxel world";
    if (Status s = checkMemory(bytesFor(size, chunkSize), what); !s) return s.error();
    VoxelWorld world;
    world.size_ = size;
    world.chunkSize_ = chunkSize;
    world.chunkShift_ = std::countr_zero(static_cast<unsigned>(chunkSize));
    for (int a = 0; a < 3; ++a) world.chunks_[a] = (size[a] + chunkSize - 1) / chunkSize;
    const std::size_t chunks =
        static_cast<std::size_t>(world.chunks_.x) * world.chunks_.y * world.chunks_.z;
    world.voxels_.assign(chunks << (3 * world.chunkShift_), Voxel{});
    world.chunkSolid_.assign(chunks, 0);
    for (int a = 0; a < 3; ++a) world.brickCount_[a] = (size[a] + kBrickSide - 1) / kBrickSide;
    world.bricks_.assign(
        static_cast<std::size_t>(world.brickCount_.x) * world.brickCount_.y * world.brickCount_.z,
        0);
    // Nothing is solid yet: every brick reaches as far as the cap allows.
    world.brickReach_.assign(world.bricks_.size() * kOctants, kMaxBrickReach);
    return world;
}

void VoxelWorld::set(int x, int y, int z, Voxel v) {
    if (!inside(x, y, z)) return;
    Voxel& slot = voxels_[index(x, y, z)];
    if (slot.solid() != v.solid()) {
        std::uint32_t& count = chunkSolid_[(static_cast<std::size_t>(z >> chunkShift_) * chunks_.y +
                                            (y >> chunkShift_)) *
                                               chunks_.x +
                                           (x >> chunkShift_)];
        count = v.solid() ? count + 1 : count - 1;
        const std::size_t brick =
            (static_cast<std::size_t>(z >> kBrickShift) * brickCount_.y + (y >> kBrickShift)) *
                brickCount_.x +
            (x >> kBrickShift);
        std::uint64_t& mask = bricks_[brick];
        if (mask == 0) emptySpaceStale_.value.store(true, std::memory_order_relaxed);
        mask ^= std::uint64_t{1} << brickBit(x, y, z);
        // A brick that lost its last solid voxel is an empty cube of side 1 in every octant: its
        // reach 0 would give traversal an empty box (inverted, left the wrong way).
        if (mask == 0) {
            for (int o = 0; o < kOctants; ++o) brickReach_[o * bricks_.size() + brick] = 1;
        }
    }
    slot = v;
}

void VoxelWorld::refreshEmptySpace() {
    if (emptySpaceCurrent()) return;
    computeBrickReach(bricks_, brickCount_, kMaxBrickReach, brickReach_);
    emptySpaceStale_.value = false;
}

std::uint64_t VoxelWorld::solidCount() const {
    return std::accumulate(chunkSolid_.begin(), chunkSolid_.end(), std::uint64_t{0});
}

bool VoxelWorld::operator==(const VoxelWorld& other) const {
    if (!(size_ == other.size_)) return false;
    if (chunkSize_ == other.chunkSize_) return voxels_ == other.voxels_;
    for (int z = 0; z < size_.z; ++z) {
        for (int y = 0; y < size_.y; ++y) {
            for (int x = 0; x < size_.x; ++x) {
                if (!(get(x, y, z) == other.get(x, y, z))) return false;
            }
        }
    }
    return true;
}

}  // namespace luxel::voxel
