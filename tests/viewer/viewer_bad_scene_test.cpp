// luxel-view refuses a pathological scene file (90,000 nested arrays, 180 KB) with one line and
// exit code 1, before any window opens: it shares the bounded JSON reader of the CLI.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_command.h"

namespace {

TEST(ViewerBadScene, DeeplyNestedSceneIsOneLineError) {
    const std::filesystem::path scene =
        std::filesystem::path(testing::TempDir()) / "viewer_deep_scene.json";
    {
        const int n = 90000;
        std::ofstream out(scene);
        out << "{\"canvas\": " << std::string(n, '[') << std::string(n, ']') << "}";
    }
    const luxel::test::RunResult r = luxel::test::runCommand(
        "DISPLAY= timeout 60 " + std::string(LUXEL_VIEW_PATH) + " " + scene.string());
    std::filesystem::remove(scene);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("viewer_deep_scene.json:1:267: invalid JSON: nesting deeper than 256 "
                            "levels"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.rfind("luxel-view: error: ", 0), 0u) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
