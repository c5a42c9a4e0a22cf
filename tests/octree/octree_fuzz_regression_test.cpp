// The invariants fuzz/octree_fuzz.cpp checks, on the files that start its corpus
// (fuzz/octree_seeds/) and on every truncation and every bit flip of their headers: any bytes
// give a tree or an Error; a tree serialises back to the same bytes and can be walked. Inputs
// that crashed the fuzz target belong here as cases of their own (none so far).
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
    EXPECT_EQ(serializeOctree(*tree), bytes) << label;
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

}  // namespace
}  // namespace luxel::octree
