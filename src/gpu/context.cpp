// Vulkan compute runtime on Vulkan-Hpp RAII, loaded at run time (no link-time libvulkan).
#include "luxel/gpu/context.h"

#include <vulkan/vulkan_raii.hpp>

#include <algorithm>
#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <optional>

#include "gpu/embedded_shaders.h"
#include "gpu/resident_libraries.h"
#include "gpu/spirv_reflect.h"
#include "luxel/core/memory.h"

namespace luxel::gpu {

class Buffer {
  public:
    vk::raii::Buffer buffer{nullptr};
    vk::raii::DeviceMemory memory{nullptr};
    std::uint64_t bytes = 0;
};

class Program {
  public:
    vk::raii::ShaderModule module{nullptr};
    vk::raii::DescriptorSetLayout setLayout{nullptr};
    vk::raii::PipelineLayout layout{nullptr};
    vk::raii::Pipeline pipeline{nullptr};
    int storageBuffers = 0;
    int pushBytes = 0;
    std::array<std::uint32_t, 3> workgroupSize{1, 1, 1};
};

struct Context::Impl {
    vk::raii::Context loader;
    vk::raii::Instance instance{nullptr};
    vk::raii::DebugUtilsMessengerEXT messenger{nullptr};
    vk::raii::PhysicalDevice physical{nullptr};
    vk::raii::Device device{nullptr};
    vk::raii::Queue queue{nullptr};
    vk::raii::CommandPool pool{nullptr};
    std::uint32_t queueFamily = 0;
    DeviceInfo info;
    double timestampPeriodNs = 1.0;
    bool timestamps = false;
    std::map<std::string, std::unique_ptr<Program>> programs;

    std::atomic<int> validationCount{0};
    mutable std::mutex messageMutex;
    std::string lastMessage;

    std::uint32_t memoryType(std::uint32_t typeBits, vk::MemoryPropertyFlags flags) const;
    std::unique_ptr<Buffer> makeBuffer(std::uint64_t bytes, vk::BufferUsageFlags usage,
                                       vk::MemoryPropertyFlags flags) const;
    void submitAndWait(const std::function<void(vk::raii::CommandBuffer&)>& record);

    // Host-visible staging kept mapped between transfers: allocating and mapping a fresh one per
    // transfer cost about 30 ms per 24 MiB on an NVIDIA H100, more than the HRC passes of a 1024^2
    // frame (docs/gpu.md). Transfers above kMaxKeptStagingBytes get a buffer of their own.
    static constexpr std::uint64_t kMaxKeptStagingBytes = std::uint64_t{256} << 20;
    std::unique_ptr<Buffer> keptStaging;
    std::byte* keptMapped = nullptr;
    // A mapped staging buffer of at least `bytes`: the kept one (grown as needed) or, for large
    // transfers, `transient`.
    std::byte* staging(std::uint64_t bytes, std::unique_ptr<Buffer>& transient, Buffer*& buffer);
};

namespace {

constexpr std::uint32_t kNoMemoryType = ~0u;

std::string versionString(std::uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
           "." + std::to_string(VK_API_VERSION_PATCH(v));
}

const char* typeName(vk::PhysicalDeviceType type) {
    switch (type) {
        case vk::PhysicalDeviceType::eDiscreteGpu:
            return "discrete";
        case vk::PhysicalDeviceType::eIntegratedGpu:
            return "integrated";
        case vk::PhysicalDeviceType::eVirtualGpu:
            return "virtual";
        case vk::PhysicalDeviceType::eCpu:
            return "cpu";
        default:
            return "other";
    }
}

DeviceInfo describe(const vk::raii::PhysicalDevice& device, int index) {
    const vk::PhysicalDeviceProperties props = device.getProperties();
    const vk::PhysicalDeviceMemoryProperties memory = device.getMemoryProperties();
    DeviceInfo info;
    info.index = index;
    info.name = props.deviceName.data();
    info.type = typeName(props.deviceType);
    info.apiVersion = versionString(props.apiVersion);
    for (std::uint32_t h = 0; h < memory.memoryHeapCount; ++h) {
        if (memory.memoryHeaps[h].flags & vk::MemoryHeapFlagBits::eDeviceLocal) {
            info.deviceLocalBytes =
                std::max<std::uint64_t>(info.deviceLocalBytes, memory.memoryHeaps[h].size);
        }
    }
    return info;
}

int preference(const DeviceInfo& d) {
    if (d.type == "discrete") return 0;
    if (d.type == "integrated") return 1;
    if (d.type == "virtual") return 2;
    return 3;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user) {
    auto* impl = static_cast<Context::Impl*>(user);
    impl->validationCount.fetch_add(1);
    std::lock_guard lock(impl->messageMutex);
    impl->lastMessage = data->pMessage ? data->pMessage : "";
    return VK_FALSE;
}

template <typename F>
auto guarded(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const vk::IncompatibleDriverError&) {
        return Error(
            "no Vulkan driver found (the loader has no compatible ICD); the GPU backend "
            "is unavailable");
    } catch (const vk::SystemError& e) {
        return Error(std::string("Vulkan: ") + e.what());
    } catch (const std::exception& e) {
        const std::string what = e.what();
        if (what.find("Failed to load vulkan library") != std::string::npos) {
            return Error(
                "no Vulkan loader (libvulkan.so.1) on this machine; the GPU backend is "
                "unavailable");
        }
        return Error("Vulkan: " + what);
    }
}

}  // namespace

std::uint32_t Context::Impl::memoryType(std::uint32_t typeBits,
                                        vk::MemoryPropertyFlags flags) const {
    const vk::PhysicalDeviceMemoryProperties memory = physical.getMemoryProperties();
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) {
            return i;
        }
    }
    return kNoMemoryType;
}

std::unique_ptr<Buffer> Context::Impl::makeBuffer(std::uint64_t bytes, vk::BufferUsageFlags usage,
                                                  vk::MemoryPropertyFlags flags) const {
    auto out = std::make_unique<Buffer>();
    out->bytes = bytes;
    out->buffer = vk::raii::Buffer(
        device, vk::BufferCreateInfo({}, std::max<std::uint64_t>(bytes, 4), usage));
    const vk::MemoryRequirements req = out->buffer.getMemoryRequirements();
    const std::uint32_t type = memoryType(req.memoryTypeBits, flags);
    if (type == kNoMemoryType) throw std::runtime_error("no suitable memory type");
    out->memory = vk::raii::DeviceMemory(device, vk::MemoryAllocateInfo(req.size, type));
    out->buffer.bindMemory(*out->memory, 0);
    return out;
}

std::byte* Context::Impl::staging(std::uint64_t bytes, std::unique_ptr<Buffer>& transient,
                                  Buffer*& buffer) {
    using M = vk::MemoryPropertyFlagBits;
    using U = vk::BufferUsageFlagBits;
    const auto usage = U::eTransferSrc | U::eTransferDst;
    if (bytes > kMaxKeptStagingBytes) {
        transient = makeBuffer(bytes, usage, M::eHostVisible | M::eHostCoherent);
        buffer = transient.get();
        return static_cast<std::byte*>(transient->memory.mapMemory(0, VK_WHOLE_SIZE));
    }
    if (!keptStaging || keptStaging->bytes < bytes) {
        // Grow to the next power of two (at least 1 MiB), so a run of growing uploads allocates a
        // handful of times.
        std::uint64_t size = std::uint64_t{1} << 20;
        while (size < bytes) size *= 2;
        keptMapped = nullptr;
        keptStaging.reset();
        keptStaging = makeBuffer(size, usage, M::eHostVisible | M::eHostCoherent);
        keptMapped = static_cast<std::byte*>(keptStaging->memory.mapMemory(0, VK_WHOLE_SIZE));
    }
    buffer = keptStaging.get();
    return keptMapped;
}

void Context::Impl::submitAndWait(const std::function<void(vk::raii::CommandBuffer&)>& record) {
    vk::raii::CommandBuffers buffers(
        device, vk::CommandBufferAllocateInfo(*pool, vk::CommandBufferLevel::ePrimary, 1));
    vk::raii::CommandBuffer& cmd = buffers.front();
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    record(cmd);
    cmd.end();
    vk::raii::Fence fence(device, vk::FenceCreateInfo());
    const vk::CommandBuffer raw = *cmd;
    queue.submit(vk::SubmitInfo({}, {}, raw), *fence);
    while (device.waitForFences(*fence, VK_TRUE, 1'000'000'000ull) == vk::Result::eTimeout) {
    }
}

Result<std::vector<DeviceInfo>> listDevices() {
    return guarded([]() -> Result<std::vector<DeviceInfo>> {
        vk::raii::Context loader;
        const vk::ApplicationInfo app("luxel", 1, "luxel", 1, VK_API_VERSION_1_3);
        vk::raii::Instance instance(loader, vk::InstanceCreateInfo({}, &app));
        std::vector<DeviceInfo> out;
        int index = 0;
        for (const vk::raii::PhysicalDevice& d : vk::raii::PhysicalDevices(instance)) {
            out.push_back(describe(d, index++));
        }
        keepLoadedLibrariesResident();
        if (out.empty()) return Error("Vulkan: the loader reports no device");
        return out;
    });
}

Result<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
    return guarded([&]() -> Result<std::unique_ptr<Context>> {
        auto impl = std::make_unique<Impl>();
        const vk::ApplicationInfo app("luxel", 1, "luxel", 1, VK_API_VERSION_1_3);
        std::vector<const char*> layers, extensions;
        if (options.validation) {
            for (const vk::LayerProperties& l : impl->loader.enumerateInstanceLayerProperties()) {
                if (std::string(l.layerName.data()) == "VK_LAYER_KHRONOS_validation") {
                    layers.push_back("VK_LAYER_KHRONOS_validation");
                    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
                }
            }
        }
        impl->instance =
            vk::raii::Instance(impl->loader, vk::InstanceCreateInfo({}, &app, layers, extensions));
        if (!layers.empty()) {
            using Severity = vk::DebugUtilsMessageSeverityFlagBitsEXT;
            using Type = vk::DebugUtilsMessageTypeFlagBitsEXT;
            impl->messenger = vk::raii::DebugUtilsMessengerEXT(
                impl->instance, vk::DebugUtilsMessengerCreateInfoEXT(
                                    {}, Severity::eWarning | Severity::eError,
                                    Type::eGeneral | Type::eValidation | Type::ePerformance,
                                    &onValidationMessage, impl.get()));
        }

        // Pick the device.
        vk::raii::PhysicalDevices devices(impl->instance);
        keepLoadedLibrariesResident();
        if (devices.empty()) return Error("Vulkan: the loader reports no device");
        std::vector<DeviceInfo> infos;
        for (std::size_t i = 0; i < devices.size(); ++i) {
            infos.push_back(describe(devices[i], static_cast<int>(i)));
        }
        int chosen = -1;
        if (options.device.empty()) {
            chosen =
                static_cast<int>(std::min_element(infos.begin(), infos.end(),
                                                  [](const DeviceInfo& a, const DeviceInfo& b) {
                                                      return preference(a) < preference(b);
                                                  }) -
                                 infos.begin());
        } else if (std::all_of(options.device.begin(), options.device.end(), ::isdigit)) {
            chosen = std::stoi(options.device);
            if (chosen >= static_cast<int>(infos.size())) {
                return Error("no Vulkan device " + options.device + " (there are " +
                             std::to_string(infos.size()) + ")");
            }
        } else {
            for (const DeviceInfo& d : infos) {
                if (d.name.find(options.device) != std::string::npos) {
                    chosen = d.index;
                    break;
                }
            }
            if (chosen < 0) return Error("no Vulkan device named like '" + options.device + "'");
        }
        impl->physical = std::move(devices[chosen]);
        impl->info = infos[chosen];
        const vk::PhysicalDeviceProperties props = impl->physical.getProperties();
        if (props.apiVersion < VK_API_VERSION_1_3) {
            return Error("Vulkan device '" + impl->info.name + "' supports only " +
                         impl->info.apiVersion + "; luxel needs 1.3");
        }

        // One compute queue.
        const auto families = impl->physical.getQueueFamilyProperties();
        bool found = false;
        for (std::uint32_t f = 0; f < families.size(); ++f) {
            if (families[f].queueFlags & vk::QueueFlagBits::eCompute) {
                impl->queueFamily = f;
                impl->timestamps = families[f].timestampValidBits > 0;
                found = true;
                break;
            }
        }
        if (!found) return Error("Vulkan device '" + impl->info.name + "' has no compute queue");
        impl->timestampPeriodNs = props.limits.timestampPeriod;
        const float priority = 1.0f;
        const vk::DeviceQueueCreateInfo queueInfo({}, impl->queueFamily, 1, &priority);
        // glslc for Vulkan 1.3 emits LocalSizeId, which needs maintenance4 (required in 1.3).
        vk::PhysicalDeviceVulkan13Features features13;
        features13.maintenance4 = VK_TRUE;
        vk::DeviceCreateInfo deviceInfo({}, queueInfo);
        deviceInfo.pNext = &features13;
        impl->device = vk::raii::Device(impl->physical, deviceInfo);
        impl->queue = vk::raii::Queue(impl->device, impl->queueFamily, 0);
        impl->pool = vk::raii::CommandPool(
            impl->device, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eTransient,
                                                    impl->queueFamily));
        return std::unique_ptr<Context>(new Context(std::move(impl)));
    });
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::~Context() = default;

const DeviceInfo& Context::device() const {
    return impl_->info;
}
int Context::validationMessages() const {
    return impl_->validationCount.load();
}
std::string Context::lastValidationMessage() const {
    std::lock_guard lock(impl_->messageMutex);
    return impl_->lastMessage;
}

Result<std::shared_ptr<Buffer>> Context::createBuffer(std::uint64_t bytes) {
    if (impl_->info.deviceLocalBytes > 0 && bytes > impl_->info.deviceLocalBytes) {
        return Error("GPU buffer of " + formatBytes(bytes) + " exceeds the device memory (" +
                     formatBytes(impl_->info.deviceLocalBytes) + ")");
    }
    return guarded([&]() -> Result<std::shared_ptr<Buffer>> {
        using U = vk::BufferUsageFlagBits;
        return std::shared_ptr<Buffer>(
            impl_->makeBuffer(bytes, U::eStorageBuffer | U::eTransferSrc | U::eTransferDst,
                              vk::MemoryPropertyFlagBits::eDeviceLocal));
    });
}

Status Context::ensureBuffer(std::shared_ptr<Buffer>& buffer, std::uint64_t& held,
                             std::uint64_t bytes) {
    if (buffer && held >= bytes) return Ok{};
    buffer.reset();
    held = 0;
    auto made = createBuffer(bytes);
    if (!made) return made.error();
    buffer = std::move(*made);
    held = bytes;
    return Ok{};
}

namespace {

// Staging buffers below this size are not checked: a check reads /proc and the cgroup files (about
// 30 us), and solvers upload dozens of small tables and parameter blocks per frame.
constexpr std::size_t kCheckedStagingBytes = std::size_t{16} << 20;

// The host-visible staging buffer lives in host memory on most devices.
Status checkStagingMemory(std::size_t bytes) {
    if (bytes < kCheckedStagingBytes) return Ok{};
    return checkMemory(bytes, "a GPU staging buffer");
}

}  // namespace

Status Context::upload(Buffer& buffer, std::span<const std::byte> data, std::uint64_t offset) {
    return uploadWith(
        buffer, data.size(),
        [&](std::span<std::byte> mapped) { std::memcpy(mapped.data(), data.data(), data.size()); },
        offset);
}

Status Context::uploadWith(Buffer& buffer, std::uint64_t bytes,
                           const std::function<void(std::span<std::byte>)>& write,
                           std::uint64_t offset) {
    LUXEL_CHECK_LE(offset + bytes, buffer.bytes);
    LUXEL_CHECK_EQ(offset % 4, 0u);
    if (bytes == 0) return Ok{};
    if (Status s = checkStagingMemory(bytes); !s) return s;
    return guarded([&]() -> Status {
        std::unique_ptr<Buffer> transient;
        Buffer* staging = nullptr;
        std::byte* mapped = impl_->staging(bytes, transient, staging);
        write(std::span(mapped, bytes));
        impl_->submitAndWait([&](vk::raii::CommandBuffer& cmd) {
            cmd.copyBuffer(*staging->buffer, *buffer.buffer, vk::BufferCopy(0, offset, bytes));
        });
        return Ok{};
    });
}

Status Context::download(const Buffer& buffer, std::span<std::byte> data) {
    LUXEL_CHECK_LE(data.size(), buffer.bytes);
    if (Status s = checkStagingMemory(data.size()); !s) return s;
    return guarded([&]() -> Status {
        std::unique_ptr<Buffer> transient;
        Buffer* staging = nullptr;
        const std::byte* mapped = impl_->staging(data.size(), transient, staging);
        impl_->submitAndWait([&](vk::raii::CommandBuffer& cmd) {
            cmd.copyBuffer(*buffer.buffer, *staging->buffer, vk::BufferCopy(0, 0, data.size()));
        });
        std::memcpy(data.data(), mapped, data.size());
        return Ok{};
    });
}

Status Context::fill(Buffer& buffer, std::uint32_t word) {
    return guarded([&]() -> Status {
        impl_->submitAndWait([&](vk::raii::CommandBuffer& cmd) {
            cmd.fillBuffer(*buffer.buffer, 0, VK_WHOLE_SIZE, word);
        });
        return Ok{};
    });
}

Result<Program*> Context::program(const std::string& shader, int storageBuffers, int pushBytes) {
    if (auto it = impl_->programs.find(shader); it != impl_->programs.end()) {
        LUXEL_CHECK_EQ(it->second->storageBuffers, storageBuffers);
        LUXEL_CHECK_EQ(it->second->pushBytes, pushBytes);
        return it->second.get();
    }
    const std::span<const std::uint32_t> words = detail::embeddedShader(shader);
    if (words.empty()) return Error("no embedded shader named '" + shader + "'");
    auto reflection = reflectSpirv(words);
    if (!reflection) return Error("shader '" + shader + "': " + reflection.error().message());
    for (std::uint32_t size : reflection->workgroupSize) {
        if (size == 0) return Error("shader '" + shader + "' declares no workgroup size");
    }
    return guarded([&]() -> Result<Program*> {
        auto p = std::make_unique<Program>();
        p->storageBuffers = storageBuffers;
        p->pushBytes = pushBytes;
        p->workgroupSize = reflection->workgroupSize;
        p->module = vk::raii::ShaderModule(
            impl_->device, vk::ShaderModuleCreateInfo({}, words.size() * 4, words.data()));
        std::vector<vk::DescriptorSetLayoutBinding> bindings;
        for (int b = 0; b < storageBuffers; ++b) {
            bindings.emplace_back(static_cast<std::uint32_t>(b), vk::DescriptorType::eStorageBuffer,
                                  1, vk::ShaderStageFlagBits::eCompute);
        }
        p->setLayout = vk::raii::DescriptorSetLayout(
            impl_->device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
        const vk::PushConstantRange range(vk::ShaderStageFlagBits::eCompute, 0,
                                          static_cast<std::uint32_t>(pushBytes));
        const vk::DescriptorSetLayout setLayout = *p->setLayout;
        p->layout = vk::raii::PipelineLayout(
            impl_->device,
            vk::PipelineLayoutCreateInfo(
                {}, setLayout,
                pushBytes > 0 ? vk::ArrayProxyNoTemporaries(range)
                              : vk::ArrayProxyNoTemporaries<const vk::PushConstantRange>()));
        const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute,
                                                      *p->module, "main");
        p->pipeline = vk::raii::Pipeline(impl_->device, nullptr,
                                         vk::ComputePipelineCreateInfo({}, stage, *p->layout));
        Program* raw = p.get();
        impl_->programs[shader] = std::move(p);
        return raw;
    });
}

std::array<std::uint32_t, 3> Context::workgroupSize(const Program& program) {
    return program.workgroupSize;
}

namespace {
// Vulkan guarantees 65535 workgroups per axis (maxComputeWorkGroupCount minimum).
constexpr std::uint64_t kMaxGroupsPerAxis = 65535;

// The workgroups a dispatch launches on each axis: ceil(threads / workgroup size), a linear
// dispatch's groups folded into rows of at most kMaxGroupsPerAxis.
Result<std::array<std::uint32_t, 3>> groupCounts(const Dispatch& d) {
    const auto& local = d.program->workgroupSize;
    std::array<std::uint64_t, 3> groups{};
    if (d.linearThreads > 0) {
        LUXEL_CHECK(local[1] == 1 && local[2] == 1);
        const std::uint64_t total = (d.linearThreads + local[0] - 1) / local[0];
        groups = {std::min(total, kMaxGroupsPerAxis),
                  (total + kMaxGroupsPerAxis - 1) / kMaxGroupsPerAxis, 1};
    } else {
        for (int a = 0; a < 3; ++a) {
            LUXEL_CHECK_GT(d.threads[a], 0u);
            groups[a] = (std::uint64_t{d.threads[a]} + local[a] - 1) / local[a];
        }
    }
    for (int a = 0; a < 3; ++a) {
        if (groups[a] > kMaxGroupsPerAxis) {
            return Error("pass '" + d.name + "' needs " + std::to_string(groups[a]) +
                         " workgroups on axis " + std::to_string(a) + "; Vulkan guarantees " +
                         std::to_string(kMaxGroupsPerAxis));
        }
    }
    return std::array<std::uint32_t, 3>{std::uint32_t(groups[0]), std::uint32_t(groups[1]),
                                        std::uint32_t(groups[2])};
}
}  // namespace

Result<std::vector<PassTiming>> Context::run(std::span<const Dispatch> dispatches) {
    std::vector<std::array<std::uint32_t, 3>> groups;
    for (const Dispatch& d : dispatches) {
        LUXEL_CHECK(d.program != nullptr);
        auto counts = groupCounts(d);
        if (!counts) return counts.error();
        groups.push_back(*counts);
        LUXEL_CHECK_EQ(static_cast<int>(d.buffers.size()), d.program->storageBuffers);
        LUXEL_CHECK_EQ(static_cast<int>(d.pushConstants.size()), d.program->pushBytes);
    }
    return guarded([&]() -> Result<std::vector<PassTiming>> {
        const auto count = static_cast<std::uint32_t>(dispatches.size());
        std::uint32_t descriptors = 0;
        for (const Dispatch& d : dispatches)
            descriptors += static_cast<std::uint32_t>(d.buffers.size());
        const vk::DescriptorPoolSize size(vk::DescriptorType::eStorageBuffer,
                                          std::max(descriptors, 1u));
        vk::raii::DescriptorPool pool(
            impl_->device,
            vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                         std::max(count, 1u), size));
        std::vector<vk::raii::DescriptorSet> sets;
        for (const Dispatch& d : dispatches) {
            const vk::DescriptorSetLayout layout = *d.program->setLayout;
            vk::raii::DescriptorSets allocated(impl_->device,
                                               vk::DescriptorSetAllocateInfo(*pool, layout));
            sets.push_back(std::move(allocated.front()));
            std::vector<vk::DescriptorBufferInfo> infos;
            for (Buffer* b : d.buffers) infos.emplace_back(*b->buffer, 0, VK_WHOLE_SIZE);
            std::vector<vk::WriteDescriptorSet> writes;
            for (std::size_t i = 0; i < infos.size(); ++i) {
                writes.emplace_back(*sets.back(), static_cast<std::uint32_t>(i), 0, 1,
                                    vk::DescriptorType::eStorageBuffer, nullptr, &infos[i]);
            }
            impl_->device.updateDescriptorSets(writes, nullptr);
        }
        vk::raii::QueryPool queries{nullptr};
        if (impl_->timestamps && count > 0) {
            queries = vk::raii::QueryPool(
                impl_->device, vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2 * count));
        }
        impl_->submitAndWait([&](vk::raii::CommandBuffer& cmd) {
            if (*queries) cmd.resetQueryPool(*queries, 0, 2 * count);
            for (std::uint32_t i = 0; i < count; ++i) {
                const Dispatch& d = dispatches[i];
                if (i > 0) {  // each pass may read what the one before wrote
                    const vk::MemoryBarrier barrier(
                        vk::AccessFlagBits::eShaderWrite,
                        vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite);
                    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                                        vk::PipelineStageFlagBits::eComputeShader, {}, barrier,
                                        nullptr, nullptr);
                }
                if (*queries) {
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries, 2 * i);
                }
                cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *d.program->pipeline);
                cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *d.program->layout, 0,
                                       *sets[i], nullptr);
                if (!d.pushConstants.empty()) {
                    cmd.pushConstants<std::byte>(
                        *d.program->layout, vk::ShaderStageFlagBits::eCompute, 0, d.pushConstants);
                }
                cmd.dispatch(groups[i][0], groups[i][1], groups[i][2]);
                if (*queries) {
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries,
                                       2 * i + 1);
                }
            }
        });
        std::vector<PassTiming> timings;
        std::vector<std::uint64_t> stamps(2 * count, 0);
        if (*queries) {
            const auto [result, values] = queries.getResults<std::uint64_t>(
                0, 2 * count, stamps.size() * sizeof(std::uint64_t), sizeof(std::uint64_t),
                vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
            (void)result;
            stamps = values;
        }
        for (std::uint32_t i = 0; i < count; ++i) {
            const double ns =
                static_cast<double>(stamps[2 * i + 1] - stamps[2 * i]) * impl_->timestampPeriodNs;
            timings.push_back({dispatches[i].name, ns * 1e-6});
        }
        return timings;
    });
}

std::vector<std::string> embeddedShaders() {
    std::vector<std::string> names;
    for (int i = 0; i < detail::kEmbeddedShaderCount; ++i) {
        names.emplace_back(detail::kEmbeddedShaders[i].name);
    }
    return names;
}

}  // namespace luxel::gpu
