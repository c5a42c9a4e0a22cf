// `luxel devices`: the Vulkan devices the GPU backend can use, with their memory.
#include <cstdio>

#include "commands/command.h"
#include "luxel/core/memory.h"
#include "luxel/gpu/context.h"

namespace luxel::cli {

Runner addDevicesCommand(CLI::App&) {
    return [] {
        auto devices = gpu::listDevices();
        if (!devices) return reportError(devices.error());
        std::printf("%-5s %-40s %-11s %-9s %s\n", "index", "name", "type", "Vulkan",
                    "device memory");
        for (const gpu::DeviceInfo& d : *devices) {
            std::printf("%-5d %-40s %-11s %-9s %s\n", d.index, d.name.c_str(), d.type.c_str(),
                        d.apiVersion.c_str(), formatBytes(d.deviceLocalBytes).c_str());
        }
        return 0;
    };
}

}  // namespace luxel::cli
