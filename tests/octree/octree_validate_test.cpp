// Hostile octree arrays get a clear error naming the problem and the entry (octree_validate.h).
#include <gtest/gtest.h>

#include <random>

#include "luxel/octree/octree_validate.h"

namespace luxel::octree {
namespace {

void expectInvalid(std::vector<std::uint32_t> nodes, int depth, const std::string& needle,
                   std::uint64_t colours = 0) {
    const Status s = validateOctree(nodes, depth, colours);
    ASSERT_FALSE(s.ok()) << needle;
    EXPECT_NE(s.error().message().find(needle), std::string::npos) << s.error().message();
}

TEST(OctreeValidate, AcceptsWellFormedTreesAndDags) {
    EXPECT_TRUE(validateOctree(std::vector<std::uint32_t>(8, 0), 1).ok());
    // Two root entries share one octant (a DAG, not a cycle).
    EXPECT_TRUE(
        validateOctree(
            std::vector<std::uint32_t>{256, 256, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8}, 2)
            .ok());
    // A shallower tree than its depth is fine (leaves may cover large cubes).
    EXPECT_TRUE(validateOctree(
                    std::vector<std::uint32_t>{256, 0, 0, 0, 0, 0, 0, 0, 9, 9, 9, 9, 9, 9, 9, 0}, 5)
                    .ok());
}

TEST(OctreeValidate, RejectsEachKindOfDamageWithItsLocation) {
    expectInvalid({}, 1, "0 entries");
    expectInvalid({0, 0, 0}, 1, "3 entries");
    expectInvalid(std::vector<std::uint32_t>(8, 0), 0, "depth 0");
    expectInvalid(std::vector<std::uint32_t>(8, 0), 17, "depth 17");
    expectInvalid({0, 0, 257, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 2,
                  "octree entry 2: branch 257 points to index 9, not the start of an octant");
    expectInvalid({0, 264, 0, 0, 0, 0, 0, 0}, 2,
                  "entry 1: branch 264 points to index 16, past the end");
    expectInvalid({0xffffffffu, 0, 0, 0, 0, 0, 0, 0}, 2, "points to index 4294967047");
    expectInvalid({0xfffffff8u + 248u - 256u, 0, 0, 0, 0, 0, 0, 0}, 2, "past the end");
    // 248 is a leaf (values below 256 are opacities), so nothing can point at the root.
    EXPECT_TRUE(validateOctree(std::vector<std::uint32_t>{248, 0, 0, 0, 0, 0, 0, 0}, 2).ok());
    // 8 -> 16 -> 8: a cycle below the root.
    expectInvalid({256, 0, 0, 0, 0, 0, 0, 0, 264, 0, 0, 0, 0, 0, 0, 0, 256, 0, 0, 0, 0, 0, 0, 0},
                  16, "a cycle");
    // A branch in an octant at the voxel level.
    expectInvalid({256, 0, 0, 0, 0, 0, 0, 0, 264, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0}, 2,
                  "deeper than its depth 2");
    expectInvalid(std::vector<std::uint32_t>(8, 0), 1, "3 colours", 3);
}

TEST(OctreeValidate, DeepSharedOctantsStillCountTheirHeight) {
    // Entry 0 reaches octant 8 directly and through 16 -> 8: octant 8's branch makes the path via
    // 16 four octants long, one more than depth 3 allows, although 8 was first met shallower.
    std::vector<std::uint32_t> nodes = {256, 264, 0, 0, 0, 0, 0, 0,   // root
                                        272, 0,   0, 0, 0, 0, 0, 0,   // 8 -> 24
                                        256, 0,   0, 0, 0, 0, 0, 0,   // 16 -> 8
                                        1,   0,   0, 0, 0, 0, 0, 0};  // 24: leaves
    expectInvalid(nodes, 3, "octree is 4 levels deep; its depth is 3");
    EXPECT_TRUE(validateOctree(nodes, 4).ok());
}

TEST(OctreeValidate, RandomArraysNeverCrashOrHang) {
    std::mt19937 rng(11);
    int accepted = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::vector<std::uint32_t> nodes(8 * (1 + rng() % 6));
        for (auto& v : nodes) {
            const unsigned kind = rng() % 4;
            v = kind == 0 ? rng() : (kind == 1 ? 248 + 8 * (rng() % 7) : rng() % 256);
        }
        accepted += validateOctree(nodes, 1 + static_cast<int>(rng() % 16)).ok() ? 1 : 0;
    }
    EXPECT_GT(accepted, 0);
    EXPECT_LT(accepted, 20000);
}

}  // namespace
}  // namespace luxel::octree
