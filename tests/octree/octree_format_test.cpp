// The octree array format (luxel/octree/octree.h) and the builder (octree_build.h).
#include <gtest/gtest.h>

#include <random>

#include "luxel/octree/octree.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_validate.h"
#include "luxel/voxel/generators.h"

namespace luxel::octree {
namespace {

// The worked example of the WebGL octree design, entry for entry.
Octree designExample() {
    Octree t;
    t.depth = 2;
    t.nodes = {256, 256, 256, 256, 0, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0};
    return t;
}

TEST(OctreeFormat, TheDesignsExampleIsOnlyTheBottomSliceOpaque) {
    const Octree t = designExample();
    ASSERT_TRUE(validateOctree(t).ok());
    EXPECT_EQ(t.side(), 4);
    EXPECT_EQ(childBase(256), 8u);
    for (int z = 0; z < 4; ++z) {
        for (int y = 0; y < 4; ++y) {
            for (int x = 0; x < 4; ++x) {
                EXPECT_EQ(opacityAt(t, {x, y, z}), y == 0 ? 255 : 0) << x << "," << y << "," << z;
            }
        }
    }
    const OctreeStats s = measure(t);
    EXPECT_EQ(s.solidVoxels, 16u);
    EXPECT_EQ(s.totalVoxels, 64u);
    EXPECT_EQ(s.octants, 2u);
    EXPECT_EQ(s.expandedOctants, 5u);  // the root and its four bottom children, unshared
}

TEST(OctreeFormat, BuildingTheBottomSliceGivesTheDesignsArray) {
    auto volume = Volume::create({4, 4, 4});
    ASSERT_TRUE(volume.ok());
    for (int z = 0; z < 4; ++z) {
        for (int x = 0; x < 4; ++x) volume->set(x, 0, z, 255);
    }
    auto tree = buildOctree(*volume);
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    EXPECT_EQ(tree->depth, 2);
    EXPECT_EQ(tree->nodes, designExample().nodes);  // de-duplicated down to one leaf octant
}

TEST(OctreeFormat, ChildSlotPutsXLowAndTheVerticalAxisHigh) {
    EXPECT_EQ(childSlot(1, 0, 0, 0), 1);
    EXPECT_EQ(childSlot(0, 0, 1, 0), 2);
    EXPECT_EQ(childSlot(0, 1, 0, 0), 4);
    EXPECT_EQ(childSlot(6, 0, 0, 2), 1);  // bit 2 of x
}

// A random volume with uniform regions, so collapse and sharing both happen.
Volume randomVolume(Int3 size, unsigned seed, bool colours) {
    std::mt19937 rng(seed);
    Volume v = *Volume::create(size, colours);
    for (int z = 0; z < size.z; ++z) {
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                const bool block = ((x >> 3) + (y >> 3) + (z >> 3)) % 3 == 0;  // solid 8^3 cubes
                const bool speck = rng() % 17 == 0;
                const std::uint8_t o = block ? 255 : (speck ? static_cast<std::uint8_t>(rng()) : 0);
                const Colour c{static_cast<std::uint8_t>(x * 7), 90, static_cast<std::uint8_t>(z),
                               1};
                v.set(x, y, z, o, block ? Colour{10, 200, 30, 1} : c);
            }
        }
    }
    return v;
}

TEST(OctreeFormat, BuiltTreesReadBackEveryVoxelAndShareOctants) {
    for (bool colours : {false, true}) {
        const Int3 size{37, 20, 29};  // not a power of two: the cube is padded with empty space
        const Volume v = randomVolume(size, 7, colours);
        auto tree = buildOctree(v, {colours});
        ASSERT_TRUE(tree.ok());
        ASSERT_TRUE(validateOctree(*tree).ok());
        EXPECT_EQ(tree->depth, 6);
        EXPECT_EQ(tree->hasColours(), colours);
        for (int z = 0; z < 64; ++z) {
            for (int y = 0; y < 64; ++y) {
                for (int x = 0; x < 64; ++x) {
                    ASSERT_EQ(opacityAt(*tree, {x, y, z}), v.opacity(x, y, z));
                    if (colours && v.opacity(x, y, z) > 0) {
                        ASSERT_EQ(colourAt(*tree, {x, y, z}), v.colour(x, y, z));
                    }
                }
            }
        }
        const OctreeStats s = measure(*tree);
        EXPECT_EQ(s.solidVoxels, v.nonZeroCount());
        EXPECT_EQ(s.reachable, s.octants);        // a fresh build holds no garbage
        EXPECT_LT(s.octants, s.expandedOctants);  // some octants are shared
    }
}

TEST(OctreeFormat, UniformVolumesCollapseToTheRoot) {
    Volume v = *Volume::create({16, 16, 16});
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) v.set(x, y, z, 80);
    auto tree = buildOctree(v);
    ASSERT_TRUE(tree.ok());
    EXPECT_EQ(tree->nodes, std::vector<std::uint32_t>(8, 80));
}

TEST(OctreeFormat, VoxelWorldsKeepTheirColoursAndSolidity) {
    auto world = voxel::VoxelWorld::create({48, 40, 48}, 16);
    ASSERT_TRUE(world.ok());
    voxel::TerrainOptions options;
    options.seed = 3;
    options.caves = true;
    ASSERT_TRUE(voxel::generateTerrain(*world, options).ok());
    auto tree = buildOctree(*world);
    ASSERT_TRUE(tree.ok());
    for (int z = 0; z < 64; ++z) {
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                const voxel::Voxel w = world->get(x, y, z);
                ASSERT_EQ(opacityAt(*tree, {x, y, z}), w.solid() ? 255 : 0);
                if (w.solid()) {
                    ASSERT_EQ(colourAt(*tree, {x, y, z}), w);
                }
            }
        }
    }
    EXPECT_EQ(measure(*tree).solidVoxels, world->solidCount());
}

}  // namespace
}  // namespace luxel::octree
