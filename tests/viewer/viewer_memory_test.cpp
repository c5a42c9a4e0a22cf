// luxel-view refuses frames that do not fit in memory before opening a window: one line, exit 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/run_command.h"

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;  // ASan's shadow memory cannot live under `ulimit -v`
#else
constexpr bool kSanitized = false;
#endif

TEST(ViewerMemory, InternalSizeThatDoesNotFitIsRefusedBeforeTheWindow) {
    if (kSanitized) GTEST_SKIP() << "address-space limits do not apply under ASan";
    const std::string scene = std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/terrain.json";
    // 3 GiB of address space; no display is needed, since the refusal comes first.
    const luxel::test::RunResult r = luxel::test::runCommand(
        "ulimit -v 3145728 && DISPLAY= timeout 60 " + std::string(LUXEL_VIEW_PATH) + " " + scene +
        " --backend cpu --size 640x360 --internal-size 32768x32768");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(
        r.output.rfind("luxel-view: error: viewing at 32768x32768 in a 640x360 window needs ", 0),
        0u)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
