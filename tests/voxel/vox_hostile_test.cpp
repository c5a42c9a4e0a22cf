// Hostile MagicaVoxel scene graphs and dicts: every one is a located Error (file, byte offset,
// what is wrong), never a crash, a hang or an allocation beyond what the file can back.
#include <gtest/gtest.h>

#include "luxel/voxel/vox_import.h"
#include "support/vox_writer.h"

namespace luxel::voxel {
namespace {

namespace vw = luxel::test::vox;

void expectError(const vw::Bytes& bytes, const std::string& text) {
    const Result<VoxImport> r = readVox(bytes, "bad.vox", {4});
    ASSERT_FALSE(r.ok()) << "expected: " << text;
    EXPECT_NE(r.error().message().find(text), std::string::npos) << r.error().message();
    EXPECT_EQ(r.error().message().rfind("bad.vox: ", 0), 0u) << r.error().message();
}

const vw::Bytes kModel = vw::model(1, 1, 1, {{0, 0, 0, 1}});

TEST(VoxHostile, CyclesInTheGraph) {
    // 0 -> group 1 -> transform 2 -> group 1 again.
    expectError(
        vw::file(vw::cat({kModel, vw::transform(0, 1), vw::group(1, {2}), vw::transform(2, 1)})),
        "node 1 is its own ancestor (a cycle in the scene graph)");
    // A transform that is its own child.
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 0)})), "node 0 is its own ancestor");
}

TEST(VoxHostile, MissingNodesModelsAndRoot) {
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 7)})), "node 7 does not exist");
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1), vw::group(1, {2, 99})})),
                "node 2 does not exist");
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1), vw::shape(1, {{5, -1}})})),
                "shape node 1 names model 5, the file has 1 (0..0)");
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1), vw::shape(1, {{-1, -1}})})),
                "names model -1");
    expectError(vw::file(vw::cat({kModel, vw::transform(3, 1), vw::shape(1, {{0, -1}})})),
                "the scene graph has no root node 0");
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1), vw::shape(1, {{0, -1}}),
                                  vw::shape(1, {{0, -1}})})),
                "node id 1 is defined twice");
}

TEST(VoxHostile, DeepNestingAndMultiplyingGroups) {
    // A chain of 300 transforms.
    vw::Bytes chain = kModel;
    for (int i = 0; i < 300; ++i) chain = vw::cat({chain, vw::transform(i, i + 1)});
    chain = vw::cat({chain, vw::shape(300, {{0, -1}})});
    expectError(vw::file(chain), "the scene graph nests deeper than 256 nodes");
    // Groups that each use the next twice: 2^20 placements from a few hundred bytes.
    vw::Bytes diamond = vw::cat({kModel, vw::transform(0, 1)});
    for (int i = 1; i <= 20; ++i) diamond = vw::cat({diamond, vw::group(i, {i + 1, i + 1})});
    diamond = vw::cat({diamond, vw::shape(21, {{0, -1}})});
    expectError(vw::file(diamond), "the scene graph places more than 65536 models");
    // The same ending in an empty group: nothing is placed, but the walk is bounded too.
    vw::Bytes hollow = vw::cat({kModel, vw::transform(0, 1)});
    for (int i = 1; i <= 40; ++i) hollow = vw::cat({hollow, vw::group(i, {i + 1, i + 1})});
    hollow = vw::cat({hollow, vw::group(41, {})});
    expectError(vw::file(hollow), "the scene graph visits more than 1048576 nodes");
}

TEST(VoxHostile, HugeTranslationsAreRefusedWithTheMemoryNeeded) {
    const vw::Bytes bytes = vw::file(vw::cat(
        {kModel, vw::transform(0, 1), vw::group(1, {2, 4}),
         vw::transform(2, 3, {{{"_t", "-1000000000 0 0"}}}), vw::shape(3, {{0, -1}}),
         vw::transform(4, 5, {{{"_t", "1000000000 5000 5000"}}}), vw::shape(5, {{0, -1}})}));
    expectError(bytes,
                "byte 8: the placed models span 2000000001x5001x5001 voxels (vox axes, from "
                "(-1000000000, 0, 0)): a world is at most 4096 per side, and this one would need");
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1, {{{"_t", "99999999999 0 0"}}}),
                                  vw::shape(1, {{0, -1}})})),
                "_t '99999999999 0 0' is not three whole numbers");
}

TEST(VoxHostile, MalformedFields) {
    expectError(
        vw::file(vw::cat({kModel, vw::transform(0, 1, {{{"_r", "3"}}}), vw::shape(1, {{0, -1}})})),
        "nTRN chunk: _r '3' is not a valid packed rotation");
    expectError(
        vw::file(vw::cat({kModel, vw::transform(0, 1, {{{"_r", "5"}}}), vw::shape(1, {{0, -1}})})),
        "_r '5' is not a valid packed rotation");  // rows 0 and 1 share a column
    expectError(vw::file(vw::cat(
                    {kModel, vw::transform(0, 1, {{{"_t", "1 2"}}}), vw::shape(1, {{0, -1}})})),
                "_t '1 2' is not three whole numbers");
    expectError(
        vw::file(vw::cat({kModel, vw::transform(0, 1, {{{"_f", "-2"}}}), vw::shape(1, {{0, -1}})})),
        "_f '-2' is not a frame index");
    // A dict that claims more entries than its chunk holds, and a string longer than the chunk.
    const vw::Bytes shortDict = vw::chunk("nGRP", vw::ints({1, 5, 0, 0}));
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1), shortDict})),
                "nGRP chunk: node attributes claims 5 entries, 8 bytes remain in the chunk");
    const vw::Bytes longString = vw::chunk("nGRP", vw::ints({1, 1, 1000, 0}));
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1), longString})),
                "nGRP chunk: node attributes claims 1000 bytes");
    const vw::Bytes manyChildren = vw::chunk("nGRP", vw::ints({1, 0, 1 << 30}));
    expectError(vw::file(vw::cat({kModel, vw::transform(0, 1), manyChildren})),
                "child count is 1073741824, but 0 bytes remain in the chunk");
    expectError(vw::file(vw::cat({kModel, vw::chunk("nTRN", vw::ints({0}))})),
                "nTRN chunk: node attributes needs 4 bytes, 0 remain in the chunk");
    expectError(vw::file(vw::cat({kModel, vw::chunk("MATL", vw::ints({3, 2}))})),
                "MATL chunk: material properties claims 2 entries");
}

TEST(VoxHostile, EveryTruncationAndByteFlipOfAGraphFileIsHandled) {
    const vw::Bytes full = vw::file(vw::cat(
        {vw::model(2, 2, 2, {{0, 0, 0, 1}, {1, 1, 1, 2}}), vw::transform(0, 1), vw::group(1, {2}),
         vw::transform(2, 3, {{{"_r", "20"}, {"_t", "4 5 6"}}}), vw::shape(3, {{0, -1}}),
         vw::layer(0, false), vw::material(1, {{"_type", "_metal"}}), vw::palette({})}));
    ASSERT_TRUE(readVox(full, "ok.vox", {4}).ok());
    for (std::size_t n = 0; n < full.size(); ++n) {
        const vw::Bytes part(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(n));
        EXPECT_FALSE(readVox(part, "cut.vox", {4}).ok()) << n;
    }
    for (std::size_t i = 0; i < full.size(); ++i) {
        for (std::uint8_t flip : {0x01, 0x80, 0xff}) {
            vw::Bytes bad = full;
            bad[i] ^= flip;
            (void)readVox(bad, "flip.vox", {4}).ok();
        }
    }
}

}  // namespace
}  // namespace luxel::voxel
