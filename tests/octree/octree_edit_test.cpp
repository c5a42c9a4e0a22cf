// Voxel edits on a DAG octree (octree_edit.h) give the tree a fresh build of the edited volume
// would give, touching only the path.
#include <gtest/gtest.h>

#include <random>

#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_edit.h"
#include "luxel/octree/octree_validate.h"

namespace luxel::octree {
namespace {

TEST(OctreeEdit, RandomEditsMatchARebuildOfTheEditedVolume) {
    for (bool colours : {false, true}) {
        Volume v = *Volume::create({32, 32, 32}, colours);
        for (int z = 0; z < 32; ++z)
            for (int x = 0; x < 32; ++x)
                for (int y = 0; y < 10; ++y) v.set(x, y, z, 255, Colour{0, 180, 0, 2});
        OctreeEditor editor(*buildOctree(v, {colours}));
        std::mt19937 rng(3);
        for (int i = 0; i < 400; ++i) {
            const Int3 c(static_cast<int>(rng() % 32), static_cast<int>(rng() % 16),
                         static_cast<int>(rng() % 32));
            const auto o = static_cast<std::uint8_t>(rng() % 3 == 0 ? 0 : rng() % 256);
            const Colour col{static_cast<std::uint8_t>(rng()), 1, 2, 3};
            ASSERT_TRUE(editor.set(c, o, col).ok());
            v.set(c.x, c.y, c.z, o, col);
        }
        ASSERT_TRUE(validateOctree(editor.tree()).ok());
        for (int z = 0; z < 32; ++z)
            for (int y = 0; y < 32; ++y)
                for (int x = 0; x < 32; ++x) {
                    ASSERT_EQ(opacityAt(editor.tree(), {x, y, z}), v.opacity(x, y, z));
                    if (colours && v.opacity(x, y, z) > 0) {
                        ASSERT_EQ(colourAt(editor.tree(), {x, y, z}), v.colour(x, y, z));
                    }
                }
        // After compaction the edited tree is as small as a fresh build of the same volume.
        editor.compact();
        ASSERT_TRUE(validateOctree(editor.tree()).ok());
        const Octree fresh = *buildOctree(v, {colours});
        EXPECT_EQ(measure(editor.tree()).octants, measure(fresh).octants);
        EXPECT_EQ(measure(editor.tree()).solidVoxels, v.nonZeroCount());
    }
}

TEST(OctreeEdit, AnEditAddsAtMostOnePathOfOctants) {
    Volume v = *Volume::create({256, 256, 256});
    Octree tree = *buildOctree(v);
    OctreeEditor editor(std::move(tree));
    const std::size_t before = editor.tree().nodes.size();
    ASSERT_TRUE(editor.set({100, 7, 200}, 255).ok());
    EXPECT_LE(editor.tree().nodes.size() - before, 8u * 7);  // depth 8: 7 octants below the root
    EXPECT_EQ(opacityAt(editor.tree(), {100, 7, 200}), 255);
    EXPECT_EQ(opacityAt(editor.tree(), {101, 7, 200}), 0);
    ASSERT_TRUE(editor.set({100, 7, 200}, 0).ok());  // undoing collapses back to one leaf
    editor.compact();
    EXPECT_EQ(editor.tree().nodes, std::vector<std::uint32_t>(8, 0));
}

}  // namespace
}  // namespace luxel::octree
