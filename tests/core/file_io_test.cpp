// Bounded whole-file reads and atomic writes (luxel/core/file_io.h).
#include "luxel/core/file_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/temp_dir.h"

namespace luxel {
namespace {

TEST(FileIo, MissingAndOversizedFilesAreRefused) {
    auto missing = readFileBytes("/nonexistent/scene.json", "scene");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message().find("cannot open scene '/nonexistent/scene.json'"),
              std::string::npos);
    const test::TempDir tmp;
    const std::string path = tmp.write("big.json", std::string(2 << 20, ' '));
    auto big = readFileBytes(path, "scene", 1 << 20);
    ASSERT_FALSE(big.ok());
    EXPECT_NE(big.error().message().find("is too large (at most 1 MiB)"), std::string::npos);
}

TEST(FileIo, AtomicWritesReplaceWholeFilesAndLeaveNoTemporary) {
    const test::TempDir tmp;
    const std::filesystem::path& dir = tmp.dir();
    const std::string path = tmp.path("out.bin");
    ASSERT_TRUE(writeFileAtomically(path, "first", "test file").ok());
    ASSERT_TRUE(writeFileAtomically(path, std::string(100000, 'x'), "test file").ok());
    auto back = readFileBytes(path, "test file");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, std::string(100000, 'x'));
    int files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1);
    const Status s = writeFileAtomically((dir / "no" / "such" / "x").string(), "a", "test file");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message().find("cannot write test file"), std::string::npos);
}

}  // namespace
}  // namespace luxel
