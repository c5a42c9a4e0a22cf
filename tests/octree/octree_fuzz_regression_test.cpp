// The invariants fuzz/octree_fuzz.cpp checks, on the files that start its corpus
// (fuzz/octree_seeds/) and on every truncation and every bit flip of their headers: any bytes
// give a tree or an Error; a tree serialises back to the same bytes and can be walked. Inputs
// that crashed the fuzz target belong here as cases of their own.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "luxel/core/file_io.h"
#include "luxel/octree/octree_file.h"
#include "luxel/octree/octree_trace.h"

namespace luxel::octree {
namespace {

std::vector<std::string> corpusFiles() {
    std::vector<std::string> files;
    const std::filesystem::path dir = std::filesystem::path(LUXEL_SOURCE_DIR) / "fuzz/octree_seeds";
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() == ".lxo") files.push_back(entry.path().string());
    }
    return files;
}

// What the fuzz target asserts for one input; returns whether it parsed.
bool checkInput(const std::string& bytes, const std::string& label) {
    const Result<Octree> tree = parseOctree(bytes, "fuzz.lxo");
    if (!tree.ok()) {
        EXPECT_FALSE(tree.error().message().empty()) << label;
        return false;
    }
    const std::string written = serializeOctree(*tree);
    if (bytes.size() >= 12 && bytes[8] == static_cast<char>(kOctreeFileVersion)) {
        EXPECT_EQ(written, bytes) << label;
    } else {
        // Version 1 is written as version 2, which reads back to itself.
        const Result<Octree> again = parseOctree(written, "written.lxo");
        EXPECT_TRUE(again.ok()) << label;
        if (again.ok()) {
            EXPECT_EQ(serializeOctree(*again), written) << label;
        }
    }
    const OctreeStats stats = measure(*tree);
    EXPECT_LE(stats.solidVoxels, stats.totalVoxels) << label;
    const Int3 e = tree->extent();
    const Vec3d centre{e.x * 0.5, e.y * 0.5, e.z * 0.5};
    for (const Vec3d& o : {Vec3d{-1.0, centre.y, centre.z}, Vec3d{-0.5, -0.25, -0.75},
                           Vec3d{e.x + 0.5, centre.y * 0.3, e.z + 0.5}}) {
        const OctreeHit hit = castRay(*tree, {o, normalize(centre - o)});
        if (hit.hit.hit) {
            EXPECT_LT(hit.entry, tree->nodes.size()) << label;
        }
    }
    return true;
}

TEST(OctreeFuzzRegression, CorpusFilesParseRoundTripAndWalk) {
    const auto files = corpusFiles();
    ASSERT_GE(files.size(), 5u);
    for (const std::string& path : files) {
        auto bytes = readFileBytes(path, "octree corpus file", 1 << 20);
        ASSERT_TRUE(bytes.ok()) << bytes.error().message();
        EXPECT_TRUE(checkInput(*bytes, path)) << path << " must be a valid octree file";
    }
}

TEST(OctreeFuzzRegression, TruncationsAndHeaderBitFlipsGiveTreesOrErrors) {
    for (const std::string& path : corpusFiles()) {
        const std::string bytes = *readFileBytes(path, "octree corpus file", 1 << 20);
        // A truncated file never matches its entry count.
        for (std::size_t n = 0; n < bytes.size(); ++n) {
            EXPECT_FALSE(checkInput(bytes.substr(0, n), path + " cut to " + std::to_string(n)));
        }
        int parsed = 0;
        for (std::size_t bit = 0; bit < 8 * kOctreeHeaderBytes; ++bit) {
            std::string flipped = bytes;
            flipped[bit / 8] = static_cast<char>(flipped[bit / 8] ^ (1 << (bit % 8)));
            parsed += checkInput(flipped, path + " bit " + std::to_string(bit)) ? 1 : 0;
        }
        // Flips of the unused high bits of the size fields can still give a valid tree; most
        // flips (magic, version, flags, count) cannot.
        EXPECT_LT(parsed, 64) << path;
    }
}

// Found by the smoke run (FuzzSmoke.octree): a mutant of a corpus file with its version set to 1
// and a size that a version 1 header (40 bytes, no colour count) accepts. It is a valid version 1
// file, so it parses; the check used to demand that it serialise to the same bytes, which only
// version 2 can: it is written as version 2, which reads back to itself.
TEST(OctreeFuzzRegression, VersionOneFileRoundTripsAsVersionTwo) {
    const unsigned char kBytes[] = {
        0x4c, 0x58, 0x4f, 0x43, 0x54, 0x52, 0x45, 0x45, 0x01, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00,
        0x00, 0x05, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x30, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x08, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x18, 0x01, 0x00, 0x00, 0x20, 0x01,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x5a, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0xff, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
    const std::string bytes(reinterpret_cast<const char*>(kBytes), sizeof kBytes);
    const Result<Octree> tree = parseOctree(bytes, "v1.lxo");
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    EXPECT_EQ(serializeOctree(*tree).substr(8, 4), std::string("\x02\0\0\0", 4));
    EXPECT_TRUE(checkInput(bytes, "version 1 file"));
}

}  // namespace
}  // namespace luxel::octree
