// The tests' temporary folders (support/temp_dir.h): fresh, private, named after the test, and gone
// with everything in them when they go.
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace luxel::test {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(TempDir, IsAFreshFolderNamedAfterTheTest) {
    const TempDir tmp;
    EXPECT_TRUE(fs::is_directory(tmp.dir()));
    EXPECT_TRUE(fs::is_empty(tmp.dir()));
    EXPECT_EQ(tmp.dir().parent_path(), fs::temp_directory_path());
    const std::string name = tmp.dir().filename().string();
    EXPECT_EQ(name.rfind("luxel_TempDir_IsAFreshFolderNamedAfterTheTest_", 0), 0u) << name;
    EXPECT_EQ(tmp.path("a.json"), (tmp.dir() / "a.json").string());
    EXPECT_FALSE(fs::exists(tmp.path("a.json")));  // path() only names the file
}

TEST(TempDir, TwoAtOnceAreTwoFolders) {
    const TempDir a;
    const TempDir b;
    EXPECT_NE(a.dir(), b.dir());
    a.write("same.txt", "a");
    b.write("same.txt", "b");
    EXPECT_EQ(slurp(a.path("same.txt")), "a");
    EXPECT_EQ(slurp(b.path("same.txt")), "b");
}

TEST(TempDir, GoesWithEverythingInIt) {
    fs::path dir;
    {
        const TempDir tmp;
        dir = tmp.dir();
        tmp.write("scene.json", "{}");
        tmp.write("textures/deep/bricks.png", "not a picture");
        fs::create_directories(tmp.dir() / "empty");
    }
    EXPECT_FALSE(fs::exists(dir)) << dir;
}

TEST(TempDir, WriteKeepsTheBytesAndMakesTheFolders) {
    const TempDir tmp;
    const std::string bytes("a\0b\r\nc", 6);
    const std::string file = tmp.write("sub/folder/bytes.bin", bytes);
    EXPECT_EQ(file, tmp.path("sub/folder/bytes.bin"));
    EXPECT_EQ(slurp(file), bytes);
    EXPECT_EQ(fs::file_size(file), 6u);
    tmp.write("sub/folder/bytes.bin", "new");  // replaces, does not append
    EXPECT_EQ(slurp(file), "new");
}

TEST(TempDir, AFileThatCannotBeWrittenIsAnError) {
    const TempDir tmp;
    fs::create_directories(tmp.dir() / "taken");
    EXPECT_THROW(tmp.write("taken", "x"), std::runtime_error);  // a folder is in the way
}

TEST(TempDir, AKeptFolderStays) {
    fs::path dir;
    {
        TempDir tmp;
        dir = tmp.dir();
        tmp.write("look.txt", "at me");
        tmp.keep();
    }
    EXPECT_EQ(slurp(dir / "look.txt"), "at me");
    fs::remove_all(dir);
}

// The fixture's folder exists for the test body and is gone with the fixture.
TEST(TempDirFixture, EachTestGetsAFolderRemovedAfterIt) {
    struct Probe : TempDirTest {
        void TestBody() override {}
        using TempDirTest::dir;
        using TempDirTest::write;
    };
    fs::path dir;
    {
        const Probe probe;
        dir = probe.dir();
        EXPECT_TRUE(fs::is_directory(dir));
        probe.write("out.png", "x");
    }
    EXPECT_FALSE(fs::exists(dir)) << dir;
}

// A parameterized test's name has a '/', which must not become a folder level.
class TempDirNames : public testing::TestWithParam<int> {};

TEST_P(TempDirNames, StayOneLevelUnderTheSystemFolder) {
    const TempDir tmp;
    EXPECT_EQ(tmp.dir().parent_path(), fs::temp_directory_path());
    const std::string name = tmp.dir().filename().string();
    EXPECT_EQ(name.rfind("luxel_Sizes_TempDirNames_StayOneLevelUnderTheSystemFolder_", 0), 0u)
        << name;
}

INSTANTIATE_TEST_SUITE_P(Sizes, TempDirNames, testing::Values(1, 2));

}  // namespace
}  // namespace luxel::test
