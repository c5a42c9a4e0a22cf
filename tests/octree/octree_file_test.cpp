// The .lxo container (octree_file.h): round trips, and damaged files give errors, not crashes.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "luxel/core/file_io.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_file.h"
#include "support/temp_dir.h"

namespace luxel::octree {
namespace {

Octree sampleTree(bool colours) {
    Volume v = *Volume::create({20, 20, 20}, colours);
    for (int z = 0; z < 20; ++z)
        for (int y = 0; y < 20; ++y)
            for (int x = 0; x < 20; ++x) {
                const int d = (x - 10) * (x - 10) + (y - 10) * (y - 10) + (z - 10) * (z - 10);
                if (d < 64)
                    v.set(x, y, z, static_cast<std::uint8_t>(255 - d), Colour{200, 10, 10, 1});
            }
    return *buildOctree(v, {colours});
}

TEST(OctreeFile, RoundTripsWithAndWithoutColours) {
    const test::TempDir tmp;
    for (bool colours : {false, true}) {
        const Octree tree = sampleTree(colours);
        const std::string path = tmp.path(std::string("round") + (colours ? "c" : "") + ".lxo");
        ASSERT_TRUE(writeOctreeFile(path, tree).ok());
        EXPECT_FALSE(std::filesystem::exists(path + ".tmp-" + std::to_string(::getpid())));
        auto back = readOctreeFile(path);
        ASSERT_TRUE(back.ok()) << back.error().message();
        EXPECT_EQ(back->depth, tree.depth);
        EXPECT_EQ(back->size, Int3(20, 20, 20));
        EXPECT_EQ(back->nodes, tree.nodes);
        EXPECT_EQ(back->colours, tree.colours);
    }
}

TEST(OctreeFile, DamagedHeadersAreNamed) {
    const std::string good = serializeOctree(sampleTree(false));
    auto expectError = [](std::string bytes, const std::string& needle) {
        auto parsed = parseOctree(bytes, "x.lxo");
        ASSERT_FALSE(parsed.ok()) << needle;
        EXPECT_NE(parsed.error().message().find(needle), std::string::npos)
            << parsed.error().message();
        EXPECT_EQ(parsed.error().message().rfind("x.lxo: ", 0), 0u);
    };
    expectError("", "not a luxel octree file");
    expectError("LXOCTREX" + good.substr(8), "not a luxel octree file");
    std::string b = good;
    b[8] = 3;
    expectError(b, "version 3 is not supported");
    b = good;
    b[12] = 40;
    expectError(b, "depth 40 is outside 1..16");
    b = good;
    b[39] = 0x7f;  // an entry count near 2^63
    expectError(b, "entries and 0 colours but");
    b = good;
    b[28] = 4;
    expectError(b, "unknown attribute layout 4");
    b = good;
    b[16] = 33;  // size x 33 in a 32^3 cube
    expectError(b, "does not fit its 32^3 cube");
    expectError(good.substr(0, good.size() - 3), "bytes follow it");
    expectError(good.substr(0, 44), "the header is cut short");
    b = good;
    b[kOctreeHeaderBytes + 1] = 0x10;  // entry 0 becomes a branch far past the end
    expectError(b, "octree entry 0: branch");
}

TEST(OctreeFile, RandomCorruptionNeverCrashes) {
    const std::string good = serializeOctree(sampleTree(true));
    std::mt19937 rng(5);
    int rejected = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::string b = good;
        const int flips = 1 + static_cast<int>(rng() % 8);
        for (int i = 0; i < flips; ++i) b[rng() % b.size()] = static_cast<char>(rng());
        if (rng() % 4 == 0) b.resize(rng() % b.size());
        rejected += parseOctree(b, "fuzz").ok() ? 0 : 1;
    }
    EXPECT_GT(rejected, 0);
}

TEST(OctreeFile, MissingFilesAndUnwritableFoldersAreErrors) {
    auto missing = readOctreeFile("/nonexistent/tree.lxo");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message().find("/nonexistent/tree.lxo"), std::string::npos);
    const Status s = writeOctreeFile("/nonexistent/tree.lxo", sampleTree(false));
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message().find("cannot write octree"), std::string::npos);
}

TEST(OctreeFile, AFailedWriteLeavesTheOldFile) {
    const test::TempDir tmp;
    const std::string path = tmp.path("keep.lxo");
    ASSERT_TRUE(writeOctreeFile(path, sampleTree(false)).ok());
    Octree broken;
    broken.nodes = {300, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_FALSE(writeOctreeFile(path, broken).ok());
    EXPECT_TRUE(readOctreeFile(path).ok());
}

}  // namespace
}  // namespace luxel::octree
