// luxel-view refuses a pathological scene file (90,000 nested arrays, 180 KB) with one line and
// exit code 1, before any window opens: it shares the bounded JSON reader of the CLI.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/run_command.h"
#include "support/temp_dir.h"

namespace {

TEST(ViewerBadScene, DeeplyNestedSceneIsOneLineError) {
    const luxel::test::TempDir tmp;
    const int n = 90000;
    const std::string scene =
        tmp.write("viewer_deep_scene.json",
                  "{\"canvas\": " + std::string(n, '[') + std::string(n, ']') + "}");
    const luxel::test::RunResult r = luxel::test::runCommand(
        "DISPLAY= timeout 60 " + std::string(LUXEL_VIEW_PATH) + " " + scene);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("viewer_deep_scene.json:1:267: invalid JSON: nesting deeper than 256 "
                            "levels"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.rfind("luxel-view: error: ", 0), 0u) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
