// GPU backends and devices: luxel.devices() and the backend argument (gpu.h).
#include "gpu.h"

namespace luxel::python {

gpu::Backend parseBackendArg(const std::string& backend) {
    return unwrap(gpu::parseBackend(backend, "backend"));
}

std::unique_ptr<gpu::Context> openBackendFor(gpu::Backend backend, const std::string& device) {
    if (backend == gpu::Backend::Cpu) return nullptr;
    Result<gpu::BackendChoice> choice = Error("");
    {
        py::gil_scoped_release release;
        choice = gpu::openBackend(backend, {device, /*validation=*/false});
    }
    if (!choice)
        throw LuxelError("backend='" + std::string(gpu::backendName(backend)) +
                         "': " + choice.error().message());
    return std::move(choice->context);
}

void bindGpu(py::module_& m) {
    m.def(
        "devices",
        [] {
            Result<std::vector<gpu::DeviceInfo>> found = Error("");
            {
                py::gil_scoped_release release;
                found = gpu::listDevices();
            }
            py::list out;
            for (const gpu::DeviceInfo& d : unwrap(std::move(found))) {
                py::dict info;
                info["index"] = d.index;
                info["name"] = d.name;
                info["type"] = d.type;
                info["memory_bytes"] = d.deviceLocalBytes;
                info["api_version"] = d.apiVersion;
                info["used_by_auto"] = gpu::autoUsesDevice(d);
                out.append(info);
            }
            return out;
        },
        "The Vulkan devices: a list of dicts (index, name, type, memory_bytes, api_version, "
        "used_by_auto). Raises luxel.Error saying why when there is no Vulkan loader or device.");
}

}  // namespace luxel::python
