// The one backend policy of the CLI, the viewer and the benches (luxel/gpu/backend_policy.h).
#include "luxel/gpu/backend_policy.h"

#include <gtest/gtest.h>

namespace luxel::gpu {
namespace {

TEST(BackendPolicy, ParsesTheThreeChoicesAndNamesThemInErrors) {
    EXPECT_EQ(*parseBackend("auto"), Backend::Auto);
    EXPECT_EQ(*parseBackend("cpu"), Backend::Cpu);
    EXPECT_EQ(*parseBackend("gpu"), Backend::Gpu);
    for (Backend b : {Backend::Auto, Backend::Cpu, Backend::Gpu}) {
        EXPECT_EQ(*parseBackend(backendName(b)), b);
    }
    auto bad = parseBackend("GPU", "--backend");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message(), "--backend 'GPU' is not one of: auto, cpu, gpu");
}

TEST(BackendPolicy, AutoSkipsOnlySoftwareDevices) {
    DeviceInfo d;
    for (const auto& [type, kind] :
         {std::pair{"discrete", DeviceKind::Discrete},
          std::pair{"integrated", DeviceKind::Integrated},
          std::pair{"virtual", DeviceKind::Virtual}, std::pair{"cpu", DeviceKind::Software},
          std::pair{"other", DeviceKind::Other}}) {
        d.type = type;
        EXPECT_EQ(deviceKind(d), kind) << type;
        EXPECT_EQ(autoUsesDevice(d), kind != DeviceKind::Software) << type;
    }
}

TEST(BackendPolicy, CpuOpensNothingAndAMissingDeviceFailsOnlyForGpu) {
    auto cpu = openBackend(Backend::Cpu, {});
    ASSERT_TRUE(cpu.ok());
    EXPECT_EQ(cpu->context, nullptr);
    EXPECT_TRUE(cpu->note.empty());
    const ContextOptions missing{.device = "no device has this name", .validation = false};
    auto gpu = openBackend(Backend::Gpu, missing);
    ASSERT_FALSE(gpu.ok());
    EXPECT_EQ(gpu.error().message().rfind("--backend gpu: ", 0), 0u) << gpu.error().message();
    auto fallback = openBackend(Backend::Auto, missing);
    ASSERT_TRUE(fallback.ok());
    EXPECT_EQ(fallback->context, nullptr);
    EXPECT_NE(fallback->note.find("no Vulkan device"), std::string::npos) << fallback->note;
}

TEST(BackendPolicy, WithADeviceGpuUsesItAndAutoUsesItUnlessSoftware) {
    auto gpu = openBackend(Backend::Gpu, {});
    if (!gpu.ok()) GTEST_SKIP() << gpu.error().message();
    ASSERT_NE(gpu->context, nullptr);
    const bool software = !autoUsesDevice(gpu->context->device());
    auto chosen = openBackend(Backend::Auto, {});
    ASSERT_TRUE(chosen.ok());
    EXPECT_EQ(chosen->context == nullptr, software);
    if (software) {
        EXPECT_NE(chosen->note.find("skipped the software Vulkan device"), std::string::npos)
            << chosen->note;
    } else {
        EXPECT_TRUE(chosen->note.empty()) << chosen->note;
    }
}

}  // namespace
}  // namespace luxel::gpu
