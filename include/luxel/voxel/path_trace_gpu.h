// The voxel path tracer on the GPU (Vulkan compute, src/gpu/shaders/voxel/path_trace.comp.glsl):
// the estimator of PathTracer (path_trace.h, its CPU reference) with the same random numbers per
// (seed, pixel, sample), traced in float instead of double, so a few paths that graze a voxel
// edge go another way and images agree with the CPU's within their standard error
// (tests/voxel/path_trace_gpu_test.cpp; docs/algorithms/voxel-path-tracing.md, "On the GPU").
// The GPU sums each pixel's samples in float; the running sums, the mean and the standard error
// are kept in double on the CPU, as PathTracer keeps them.
#pragma once

#include <cstdint>
#include <memory>

#include "luxel/core/error.h"
#include "luxel/gpu/fwd.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/path_trace_sums.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

class VoxelGpuRenderer;

// Most path samples (pixels x samples) one dispatch traces, so no dispatch runs long enough for a
// display driver's watchdog; bigger passes are split into bands of rows and chunks of samples.
inline constexpr std::int64_t kMaxPathsPerDispatch = std::int64_t(1) << 18;
// Most samples per pixel summed in float on the GPU before the sums are added to the CPU's doubles.
inline constexpr int kPathSamplesPerDownload = 64;

// The GPU tracer's memory at width x height with `emitters` emissive voxels
// (PathEmitters::find): the host's running sums and download, the world's upload, the sums and
// the emitters on the device.
PathTraceMemory estimatePathTraceGpuMemory(const VoxelWorld& world, const TextureSet* textures,
                                           int width, int height, int emitters);

class PathTracerGpu {
  public:
    // Uploads the world, textures, materials and emitters to `context`, which, with the world
    // and the textures, must outlive the tracer. The same checks as PathTracer::create, plus the
    // device's memory (estimatePathTraceGpuMemory), refused with the bytes.
    static Result<PathTracerGpu> create(gpu::Context& context, const VoxelWorld& world,
                                        const Camera& camera, const ShadeOptions& shading,
                                        const PathTraceOptions& options,
                                        const TextureSet* textures = nullptr);
    // The same over a world already uploaded by `uploaded` (VoxelGpuRenderer::create of `world`
    // and its textures on `context`), which must outlive the tracer: the viewer's progressive
    // mode traces over the ray caster's upload and restarts its tracer for each new view.
    static Result<PathTracerGpu> create(gpu::Context& context, VoxelGpuRenderer& uploaded,
                                        const VoxelWorld& world, const Camera& camera,
                                        const ShadeOptions& shading,
                                        const PathTraceOptions& options);
    PathTracerGpu(PathTracerGpu&&) noexcept;
    PathTracerGpu& operator=(PathTracerGpu&&) noexcept;
    ~PathTracerGpu();

    // Adds samples samplesDone() .. samplesDone() + count - 1 of every pixel, as
    // PathTracer::addSamples. Fails when the total would exceed kMaxPathSamples, and with the
    // device's error (the samples of the downloads before it stay added: see samplesDone()).
    Status addSamples(int count);
    int samplesDone() const;
    PathTraceImage image() const;
    // GPU time of the dispatches of the last addSamples, in milliseconds.
    double lastGpuMilliseconds() const;

    // Starts a new accumulation (0 samples) of another view, light or options over the same
    // world upload, as create would: nothing of the world is sent again (a new camera sends
    // its parameters), the emitters are found and sent again only when the world's generation
    // (VoxelGpuRenderer::worldGeneration: after updateRegion) or the materials' emission
    // changed, and the sums are reallocated only for a larger image. The same checks as create;
    // after a failure the tracer holds no samples (and, when the failure came from the device,
    // adds none until a restart succeeds).
    Status restart(const Camera& camera, const ShadeOptions& shading,
                   const PathTraceOptions& options);
    // The world upload the tracer reads: its own, or the one given to create.
    const VoxelGpuRenderer& uploaded() const;
    // Bytes of emitters sent to the device since create.
    std::uint64_t emitterUploadBytes() const;

  private:
    struct State;
    explicit PathTracerGpu(std::unique_ptr<State> state);
    static Result<PathTracerGpu> make(gpu::Context& context, VoxelGpuRenderer* uploaded,
                                      const VoxelWorld& world, const Camera& camera,
                                      const ShadeOptions& shading, const PathTraceOptions& options,
                                      const TextureSet* textures);
    std::unique_ptr<State> state_;
};

// PathTracerGpu with options.samplesPerPixel samples in one pass.
Result<PathTraceImage> pathTraceGpu(gpu::Context& context, const VoxelWorld& world,
                                    const Camera& camera, const ShadeOptions& shading,
                                    const PathTraceOptions& options,
                                    const TextureSet* textures = nullptr);

}  // namespace luxel::voxel
