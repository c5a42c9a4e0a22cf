#include "luxel/gpu/backend_policy.h"

namespace luxel::gpu {

Result<Backend> parseBackend(std::string_view text, std::string_view option) {
    if (text == "auto") return Backend::Auto;
    if (text == "cpu") return Backend::Cpu;
    if (text == "gpu") return Backend::Gpu;
    return Error(std::string(option) + " '" + std::string(text) +
                 "' is not one of: auto, cpu, gpu");
}

const char* backendName(Backend backend) {
    switch (backend) {
        case Backend::Auto:
            return "auto";
        case Backend::Cpu:
            return "cpu";
        case Backend::Gpu:
            return "gpu";
    }
    return "auto";
}

DeviceKind deviceKind(const DeviceInfo& device) {
    if (device.type == "discrete") return DeviceKind::Discrete;
    if (device.type == "integrated") return DeviceKind::Integrated;
    if (device.type == "virtual") return DeviceKind::Virtual;
    if (device.type == "cpu") return DeviceKind::Software;
    return DeviceKind::Other;
}

bool autoUsesDevice(const DeviceInfo& device) {
    return deviceKind(device) != DeviceKind::Software;
}

Result<BackendChoice> openBackend(Backend backend, const ContextOptions& options) {
    BackendChoice choice;
    if (backend == Backend::Cpu) return choice;
    auto context = Context::create(options);
    if (!context) {
        if (backend == Backend::Gpu) return Error("--backend gpu: " + context.error().message());
        choice.note = "no Vulkan device (" + context.error().message() + "); using the CPU";
        return choice;
    }
    if (backend == Backend::Auto && !autoUsesDevice((*context)->device())) {
        choice.note = "auto: skipped the software Vulkan device " + (*context)->device().name +
                      " (slower than the CPU path); using the CPU";
        return choice;
    }
    choice.context = std::move(*context);
    return choice;
}

}  // namespace luxel::gpu
