// A test fixture for running the `luxel` command line: a fresh folder per test (named after the
// fixture and the test, removed afterwards), files written into it, and the one-line error check
// every bad-input test makes.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_command.h"

namespace luxel::test {

inline RunResult runLuxel(const std::string& args) {
    return runCommand(std::string(LUXEL_CLI_PATH) + " " + args);
}

class CliFixture : public testing::Test {
  protected:
    void SetUp() override {
        const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
        // The process id keeps two test runs at once (two build trees) out of each other's way.
        dir_ = std::filesystem::temp_directory_path() /
               ("luxel_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
                std::to_string(getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        const std::filesystem::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // A run that must fail with exit code 1 and one "luxel: error:" line containing `needle`.
    void expectError(const std::string& args, const std::string& needle) {
        const RunResult r = runLuxel(args);
        EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("luxel: error: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(needle), std::string::npos)
            << "expected '" << needle << "' in: " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }

    std::filesystem::path dir_;
};

}  // namespace luxel::test
