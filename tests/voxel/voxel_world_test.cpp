// Chunked dense voxel storage: addressing, chunk counts, bounds, bad sizes.
#include <gtest/gtest.h>

#include "luxel/core/memory.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {
namespace {

TEST(VoxelWorld, StoresEveryVoxelAtItsOwnAddress) {
    VoxelWorld world = VoxelWorld::create({37, 20, 9}, 8).value();
    EXPECT_EQ(world.chunkCount(), (Int3{5, 3, 2}));
    for (int z = 0; z < 9; ++z) {
        for (int y = 0; y < 20; ++y) {
            for (int x = 0; x < 37; ++x) {
                world.set(x, y, z,
                          {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y),
                           static_cast<std::uint8_t>(z), 255});
            }
        }
    }
    for (int z = 0; z < 9; ++z) {
        for (int y = 0; y < 20; ++y) {
            for (int x = 0; x < 37; ++x) {
                const Voxel v = world.get(x, y, z);
                ASSERT_EQ(v.r, x);
                ASSERT_EQ(v.g, y);
                ASSERT_EQ(v.b, z);
            }
        }
    }
    EXPECT_EQ(world.solidCount(), 37u * 20 * 9);
}

TEST(VoxelWorld, ChunkSolidCountsFollowEdits) {
    VoxelWorld world = VoxelWorld::create({64, 64, 64}, 32).value();
    EXPECT_EQ(world.chunkSolidCount(1, 0, 1), 0u);
    world.set(40, 3, 33, {1, 2, 3, 255});
    world.set(40, 3, 33, {9, 9, 9, 255});  // repainting a solid voxel does not count twice
    world.set(41, 3, 33, {1, 2, 3, 255});
    EXPECT_EQ(world.chunkSolidCount(1, 0, 1), 2u);
    world.set(40, 3, 33, {});
    EXPECT_EQ(world.chunkSolidCount(1, 0, 1), 1u);
    EXPECT_EQ(world.solidCount(), 1u);
}

TEST(VoxelWorld, OutsideReadsEmptyAndWritesAreIgnored) {
    VoxelWorld world = VoxelWorld::create({4, 4, 4}, 4).value();
    world.set(-1, 0, 0, {1, 1, 1, 255});
    world.set(4, 0, 0, {1, 1, 1, 255});
    EXPECT_FALSE(world.solid(-1, 0, 0));
    EXPECT_FALSE(world.solid(0, 0, 4));
    EXPECT_EQ(world.solidCount(), 0u);
}

TEST(VoxelWorld, RejectsBadSizesAndChunkSizes) {
    EXPECT_FALSE(VoxelWorld::create({0, 4, 4}).ok());
    EXPECT_FALSE(VoxelWorld::create({4, -1, 4}).ok());
    EXPECT_FALSE(VoxelWorld::create({kMaxWorldSide + 1, 4, 4}).ok());
    EXPECT_FALSE(VoxelWorld::create({8, 8, 8}, 6).ok());
    EXPECT_FALSE(VoxelWorld::create({8, 8, 8}, 256).ok());
    auto absurd = VoxelWorld::create({4096, 4096, 4096});  // 256 GiB
    ASSERT_FALSE(absurd.ok());
    EXPECT_NE(absurd.error().message().find("only"), std::string::npos) << absurd.error().message();
}

TEST(VoxelWorld, MemoryEstimateCoversWholeChunks) {
    // 512^3 in 32^3 chunks: 4 bytes per voxel plus a counter per chunk, and per 4^3 brick an
    // 8-byte mask and 8 reach bytes (one per direction octant).
    EXPECT_EQ(VoxelWorld::bytesFor({512, 512, 512}, 32), 512ull * 512 * 512 * 4 + 16 * 16 * 16 * 4 +
                                                             512ull * 512 * 512 / 8 +
                                                             512ull * 512 * 512 / 8);
    EXPECT_EQ(VoxelWorld::bytesFor({33, 1, 1}, 32),
              2ull * 32 * 32 * 32 * 4 + 2 * 4 + 2 * 32 * 32 * 32 / 8 + 2 * 32 * 32 * 32 / 8);
}

}  // namespace
}  // namespace luxel::voxel

namespace luxel::voxel {
namespace {

TEST(VoxelWorld, EqualityIgnoresTheChunkSize) {
    VoxelWorld a = VoxelWorld::create({20, 10, 5}, 4).value();
    VoxelWorld b = VoxelWorld::create({20, 10, 5}, 16).value();
    EXPECT_TRUE(a == b);
    a.set(19, 9, 4, {1, 2, 3, 255});
    EXPECT_FALSE(a == b);
    b.set(19, 9, 4, {1, 2, 3, 255});
    EXPECT_TRUE(a == b);
    EXPECT_FALSE(a == VoxelWorld::create({20, 10, 6}, 4).value());
}

}  // namespace
}  // namespace luxel::voxel
