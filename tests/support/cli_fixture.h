// A test fixture for running the `luxel` command line: a fresh folder per test (TempDirTest),
// files written into it, and the one-line error check every bad-input test makes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/run_command.h"
#include "support/temp_dir.h"

namespace luxel::test {

inline RunResult runLuxel(const std::string& args) {
    return runCommand(std::string(LUXEL_CLI_PATH) + " " + args);
}

class CliFixture : public TempDirTest {
  protected:
    // A run that must fail with exit code 1 and one "luxel: error:" line containing `needle`.
    void expectError(const std::string& args, const std::string& needle) {
        const RunResult r = runLuxel(args);
        EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("luxel: error: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(needle), std::string::npos)
            << "expected '" << needle << "' in: " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
};

}  // namespace luxel::test
