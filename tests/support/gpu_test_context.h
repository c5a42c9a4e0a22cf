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

}  // namespace luxel::test
