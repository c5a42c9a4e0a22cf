// The backend argument every render takes ("auto", "cpu", "gpu") and the GPU context it opens,
// by luxel's one policy (luxel/gpu/backend_policy.h).
#pragma once

#include <memory>
#include <string>

#include "bindings.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"

namespace luxel::python {

gpu::Backend parseBackendArg(const std::string& backend);

// The context to render on, or null for the CPU ("auto" without a hardware device, "cpu").
// "gpu" without a usable Vulkan device raises luxel.Error saying why. Releases the GIL while the
// devices are probed.
std::unique_ptr<gpu::Context> openBackendFor(gpu::Backend backend, const std::string& device);

}  // namespace luxel::python
