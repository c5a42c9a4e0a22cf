// The last resort of luxel and luxel-view (apps/common/last_resort.h): allocation failures that no
// estimate caught become one error line and exit code 1.
#include "common/last_resort.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace {

using luxel::options::runUntilOutOfMemory;

TEST(LastResort, BadAllocBecomesOneLineAndExitCodeOne) {
    testing::internal::CaptureStderr();
    const int code =
        runUntilOutOfMemory("luxel", "running 'render'", []() -> int { throw std::bad_alloc(); });
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(code, 1);
    EXPECT_EQ(err,
              "luxel: error: out of memory while running 'render'; try a smaller --size or free "
              "some memory\n");
}

TEST(LastResort, AbsurdVectorSizeIsCaughtToo) {
    testing::internal::CaptureStderr();
    const int code = runUntilOutOfMemory("luxel-view", "viewing the scene", [] {
        std::vector<double> v;
        v.reserve(v.max_size() + 1);  // std::length_error
        return 0;
    });
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(code, 1);
    EXPECT_EQ(
        err.rfind("luxel-view: error: a size too large to allocate while viewing the scene", 0), 0u)
        << err;
}

TEST(LastResort, ThreadThatCannotStartIsCaught) {
    testing::internal::CaptureStderr();
    const int code = runUntilOutOfMemory("luxel", "running 'render'", []() -> int {
        throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
    });
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(code, 1);
    EXPECT_EQ(err.rfind("luxel: error: out of system resources (", 0), 0u) << err;
}

TEST(LastResort, NormalRunsPassTheirExitCodeThrough) {
    EXPECT_EQ(runUntilOutOfMemory("luxel", "x", [] { return 0; }), 0);
    EXPECT_EQ(runUntilOutOfMemory("luxel", "x", [] { return 1; }), 1);
    // Other exceptions are not memory failures and are not turned into this message.
    EXPECT_THROW(
        runUntilOutOfMemory("luxel", "x", []() -> int { throw std::runtime_error("other"); }),
        std::runtime_error);
}

}  // namespace
