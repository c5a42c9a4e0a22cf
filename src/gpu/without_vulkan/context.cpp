// The GPU runtime of a build without the GPU backend (LUXEL_GPU=OFF): the same API, no Vulkan
// headers, no shaders. No context can be opened, so every caller takes its CPU path, exactly as on
// a machine without a Vulkan driver (docs/gpu.md).
#include "luxel/gpu/context.h"

#include "gpu/embedded_shaders.h"

namespace luxel::gpu {

class Buffer {};
class Program {};
struct Context::Impl {
    DeviceInfo info;
};

namespace detail {

const EmbeddedShader kEmbeddedShaders[1] = {};
const int kEmbeddedShaderCount = 0;
const bool kShadersEmbedded = false;

}  // namespace detail

namespace {

Error withoutBackend() {
    return Error("luxel was built without the GPU backend (LUXEL_GPU=OFF)");
}

}  // namespace

Result<std::vector<DeviceInfo>> listDevices() {
    return withoutBackend();
}

Result<std::unique_ptr<Context>> Context::create(const ContextOptions&) {
    return withoutBackend();
}

// No Context is ever made in this build; the members exist so that the libraries calling them
// link, and fail cleanly should one be reached anyway.
Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::~Context() = default;

const DeviceInfo& Context::device() const {
    return impl_->info;
}
int Context::validationMessages() const {
    return 0;
}
std::string Context::lastValidationMessage() const {
    return {};
}
Result<std::shared_ptr<Buffer>> Context::createBuffer(std::uint64_t) {
    return withoutBackend();
}
Status Context::upload(Buffer&, std::span<const std::byte>, std::uint64_t) {
    return withoutBackend();
}
Status Context::uploadWith(Buffer&, std::uint64_t, const std::function<void(std::span<std::byte>)>&,
                           std::uint64_t) {
    return withoutBackend();
}
Status Context::download(const Buffer&, std::span<std::byte>) {
    return withoutBackend();
}
Status Context::fill(Buffer&, std::uint32_t) {
    return withoutBackend();
}
Result<Program*> Context::program(const std::string&, int, int) {
    return withoutBackend();
}
std::array<std::uint32_t, 3> Context::workgroupSize(const Program&) {
    return {1, 1, 1};
}
Result<std::vector<PassTiming>> Context::run(std::span<const Dispatch>) {
    return withoutBackend();
}

std::vector<std::string> embeddedShaders() {
    return {};
}

}  // namespace luxel::gpu
