// The Vulkan compute runtime: instance, device, one compute queue, buffers, compute programs from
// the embedded SPIR-V, and named, timed dispatches. Headless; Vulkan is loaded at run time, so a
// machine without a loader or device gets an Error (and the caller its CPU path), never a crash.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "luxel/core/error.h"

namespace luxel::gpu {

struct DeviceInfo {
    int index = 0;
    std::string name;
    std::string type;  // "discrete", "integrated", "virtual", "cpu", "other"
    std::uint64_t deviceLocalBytes = 0;
    std::string apiVersion;  // "1.3.238"
};

// Every Vulkan device the loader reports, or an Error saying why there is none.
Result<std::vector<DeviceInfo>> listDevices();

struct ContextOptions {
    // "" = prefer a discrete GPU, then integrated, then anything (lavapipe included); a number
    // picks that index of listDevices(); otherwise the first device whose name contains it.
    std::string device;
    // Enable VK_LAYER_KHRONOS_validation when installed; messages are counted (validationMessages).
    bool validation = false;
};

class Buffer;
class Program;
struct Dispatch;

// Timing of one named dispatch, from timestamp queries.
struct PassTiming {
    std::string name;
    double milliseconds = 0;
};

class Context {
  public:
    static Result<std::unique_ptr<Context>> create(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const DeviceInfo& device() const;
    // Validation-layer warnings and errors seen so far (0 when validation is off).
    int validationMessages() const;
    std::string lastValidationMessage() const;

    // A device-local storage buffer of `bytes` (shared: it outlives nothing but the context);
    // fails when the device memory would not fit.
    Result<std::shared_ptr<Buffer>> createBuffer(std::uint64_t bytes);
    // `buffer` (of `held` bytes) holding at least `bytes`: kept when it does, else made anew at
    // `bytes`, the old one freed first so the two never hold device memory at once. On failure
    // `buffer` is empty and `held` 0.
    Status ensureBuffer(std::shared_ptr<Buffer>& buffer, std::uint64_t& held, std::uint64_t bytes);
    // Copies `data` into the buffer at byte `offset` (a multiple of 4).
    Status upload(Buffer& buffer, std::span<const std::byte> data, std::uint64_t offset = 0);
    // Copies `bytes` into the buffer at `offset` that `write` puts straight into the mapped
    // staging memory: data packed for the GPU is written once, not packed into a vector first
    // and copied from it.
    Status uploadWith(Buffer& buffer, std::uint64_t bytes,
                      const std::function<void(std::span<std::byte>)>& write,
                      std::uint64_t offset = 0);
    Status download(const Buffer& buffer, std::span<std::byte> data);
    // Sets every 32-bit word of the buffer to `word` on the device (0: zeroes it).
    Status fill(Buffer& buffer, std::uint32_t word = 0);

    // The compute program of an embedded shader (cached by name). `storageBuffers` bindings
    // 0..n-1 in set 0 and a push-constant block of `pushBytes` (both checked at dispatch).
    Result<Program*> program(const std::string& shader, int storageBuffers, int pushBytes);
    // The workgroup size the program's shader declares.
    static std::array<std::uint32_t, 3> workgroupSize(const Program& program);

    // Records and runs dispatches in one submission; returns their GPU times.
    Result<std::vector<PassTiming>> run(std::span<const Dispatch> dispatches);

    struct Impl;

  private:
    explicit Context(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// One compute dispatch of a program over `threads` invocations, with its buffers and push
// constants. The workgroup size is the shader's own (read from its SPIR-V when the program is
// made), so it is declared once, in the shared header the shader's local_size uses; the runtime
// launches ceil(threads / workgroup size) groups on each axis and the shader discards the excess.
struct Dispatch {
    std::string name;  // the pass's name in timings
    Program* program = nullptr;
    std::vector<Buffer*> buffers;
    std::vector<std::byte> pushConstants;
    std::uint32_t threads[3] = {0, 0, 0};
    std::uint64_t linearThreads = 0;  // set by setLinearThreads

    void setThreads(std::uint64_t x, std::uint64_t y = 1, std::uint64_t z = 1) {
        threads[0] = static_cast<std::uint32_t>(x);
        threads[1] = static_cast<std::uint32_t>(y);
        threads[2] = static_cast<std::uint32_t>(z);
        linearThreads = 0;
    }

    // `count` invocations of a shader with a one-dimensional workgroup, which reads its index as
    // LUXEL_LINEAR_INVOCATION (glsl_compat.h) and discards the excess. Context::run folds the
    // groups into rows of at most 65535 (Vulkan guarantees no more per axis), so counts of
    // millions (large worlds' probes times bins, long ray batches) need no splitting by callers.
    void setLinearThreads(std::uint64_t count) {
        threads[0] = threads[1] = threads[2] = 1;
        linearThreads = count;
    }

    template <typename T>
    void setPush(const T& value) {
        pushConstants.resize(sizeof(T));
        std::memcpy(pushConstants.data(), &value, sizeof(T));
    }
};

// Names of the embedded shaders.
std::vector<std::string> embeddedShaders();

}  // namespace luxel::gpu
