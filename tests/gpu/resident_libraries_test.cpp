// After a Vulkan probe the loader and the drivers stay loaded (src/gpu/resident_libraries.h), so
// a driver's one-time allocations stay reachable: `luxel devices` then ends cleanly under
// LeakSanitizer too (in the asan preset a leak report would make it exit non-zero).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <string>

#include "luxel/gpu/context.h"
#include "support/run_command.h"

namespace {

bool loaded(const char* name) {
    void* handle = dlopen(name, RTLD_LAZY | RTLD_NOLOAD);
    if (handle == nullptr) return false;
    dlclose(handle);  // drops only the reference this lookup added
    return true;
}

TEST(GpuRuntimeResident, LoaderStaysLoadedAfterTheInstanceIsGone) {
    auto devices = luxel::gpu::listDevices();
    if (!devices) GTEST_SKIP() << devices.error().message();
    // listDevices destroyed its instance and its loader handle; the loader is still mapped.
    EXPECT_TRUE(loaded("libvulkan.so.1") || loaded("libvulkan.so"));
}

TEST(GpuRuntimeResident, DevicesCommandEndsWithoutALeakReport) {
    if (!luxel::gpu::listDevices()) GTEST_SKIP() << "no Vulkan device";
    const luxel::test::RunResult r =
        luxel::test::runCommand(std::string(LUXEL_CLI_PATH) + " devices");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("LeakSanitizer"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("device memory"), std::string::npos) << r.output;
}

}  // namespace
