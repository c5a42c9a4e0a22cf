// A private folder under the system temporary directory for the files a test writes, removed with
// everything in it when the test ends, passed or failed. TempDir is the folder itself (for a test
// or helper that wants one of its own); TempDirTest is a GoogleTest fixture holding one per test.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace luxel::test {

class TempDir {
  public:
    // Named luxel_<suite>_<test>_XXXXXX after the running test (to find it when it is kept);
    // mkdtemp makes the name unique, so tests running at once in one or many processes never
    // share a folder.
    TempDir() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / ("luxel_" + testLabel() + "_XXXXXX"))
                .string();
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        if (::mkdtemp(name.data()) == nullptr) {
            throw std::filesystem::filesystem_error(
                "cannot make a temporary folder", pattern,
                std::error_code(errno, std::generic_category()));
        }
        dir_ = name.data();
    }
    ~TempDir() {
        if (keep_) return;
        std::error_code ignored;  // a destructor must not throw; nothing more can be done
        std::filesystem::remove_all(dir_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& dir() const { return dir_; }
    // The path of `name` (a file or a relative path) inside the folder; nothing is created.
    std::string path(std::string_view name) const { return (dir_ / name).string(); }
    // Writes `content` byte for byte to `name` inside the folder, making the folders on its way,
    // and returns its path. A file that cannot be written stops the test with the reason.
    std::string write(std::string_view name, std::string_view content) const {
        const std::filesystem::path file = dir_ / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream out(file, std::ios::binary);
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        out.close();
        if (!out) throw std::runtime_error("cannot write the test file '" + file.string() + "'");
        return file.string();
    }
    // Leaves the folder in place when this TempDir goes, for a look at what a test wrote.
    void keep() { keep_ = true; }

  private:
    // "<suite>_<test>" of the running test with anything but letters, digits, '-' and '_' (the
    // '/' of parameterized tests) made '_', shortened to stay far below the file name limit.
    static std::string testLabel() {
        const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
        std::string label =
            info ? std::string(info->test_suite_name()) + "_" + info->name() : std::string("test");
        for (char& c : label) {
            const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                               (c >= '0' && c <= '9') || c == '-' || c == '_';
            if (!plain) c = '_';
        }
        return label.substr(0, 100);
    }

    std::filesystem::path dir_;
    bool keep_ = false;
};

// A fixture whose every test gets a fresh TempDir, made before SetUp and removed after TearDown.
class TempDirTest : public testing::Test {
  protected:
    const std::filesystem::path& dir() const { return tempDir_.dir(); }
    std::string path(std::string_view name) const { return tempDir_.path(name); }
    std::string write(std::string_view name, std::string_view content) const {
        return tempDir_.write(name, content);
    }
    TempDir& tempDir() { return tempDir_; }

  private:
    TempDir tempDir_;
};

}  // namespace luxel::test
