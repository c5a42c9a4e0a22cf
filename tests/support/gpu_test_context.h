// The Vulkan context the GPU tests share: created once, with validation on, on the first device
// (Mesa's lavapipe where there is no hardware GPU); null where there is no Vulkan device, so tests
// skip with the reason from gpu::Context::create().
#pragma once

#include <memory>

#include "luxel/gpu/context.h"

namespace luxel::test {

inline gpu::Context* sharedGpuContext() {
    static std::unique_ptr<gpu::Context> context = [] {
        auto created = gpu::Context::create({.device = "", .validation = true});
        return created ? std::move(*created) : nullptr;
    }();
    return context.get();
}

// A context of its own for a test that counts validation messages from a clean start; null where
// there is no Vulkan device.
inline std::unique_ptr<gpu::Context> freshGpuContext() {
    auto context = gpu::Context::create({.device = "", .validation = true});
    return context ? std::move(*context) : nullptr;
}

}  // namespace luxel::test

// Declares `context`, a fresh context, or skips the test with the reason there is none.
#define LUXEL_REQUIRE_GPU(context)                   \
    auto context = ::luxel::test::freshGpuContext(); \
    if (!context)                                    \
    GTEST_SKIP() << "no Vulkan device: " << ::luxel::gpu::Context::create().error().message()
