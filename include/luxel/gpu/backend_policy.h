// Which backend a render runs on, decided in one place for the CLI, the viewer and the benches:
//   cpu  - the CPU path;
//   gpu  - a Vulkan device of any kind (a software one such as lavapipe included), or an error
//          naming why none could be opened;
//   auto - a hardware Vulkan device when there is one; otherwise the CPU, with a note saying why
//          (no device, or only a software device, which is slower than the CPU path).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "luxel/core/error.h"
#include "luxel/gpu/context.h"

namespace luxel::gpu {

enum class Backend { Auto, Cpu, Gpu };

// "auto", "cpu" or "gpu"; anything else is an error naming `option` and the choices.
Result<Backend> parseBackend(std::string_view text, std::string_view option = "--backend");
const char* backendName(Backend backend);

enum class DeviceKind { Discrete, Integrated, Virtual, Software, Other };

DeviceKind deviceKind(const DeviceInfo& device);

// Whether `auto` uses this device: every kind but a software device.
bool autoUsesDevice(const DeviceInfo& device);

struct BackendChoice {
    std::unique_ptr<Context> context;  // null: run on the CPU
    std::string note;                  // why auto chose the CPU (empty otherwise)
};

// Opens the backend by the policy above.
Result<BackendChoice> openBackend(Backend backend, const ContextOptions& options);

}  // namespace luxel::gpu
