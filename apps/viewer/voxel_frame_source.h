// The backend seam of voxel mode: something that turns a world and a camera into a picture, on
// the CPU (the library's ray caster) or the GPU (VoxelGpuRenderer, which re-uploads edited
// chunks in worldEdited).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frame.h"
#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::gpu {
class Context;
}  // namespace luxel::gpu

namespace luxel::voxel {
class VoxelGpuRenderer;
}  // namespace luxel::voxel

namespace luxel::viewer {

// The world as a GPU source has uploaded it: what the GPU path tracer traces (both null on the
// CPU).
struct GpuWorld {
    gpu::Context* context = nullptr;
    voxel::VoxelGpuRenderer* renderer = nullptr;
};

class VoxelFrameSource {
  public:
    virtual ~VoxelFrameSource() = default;
    virtual std::string backend() const = 0;  // "cpu" or "gpu"
    virtual std::string device() const = 0;   // shown in the overlay
    // A hardware GPU, fast enough to render the full window (lavapipe and the CPU are not).
    virtual bool hardwareGpu() const = 0;
    // The world's face textures, which the CPU solvers (sky visibility, the path tracer) read too.
    virtual const voxel::TextureSet& textures() const = 0;
    // The uploaded world, for the progressive path tracer to run on the same device.
    virtual GpuWorld gpuWorld() { return {}; }
    // The world changed inside [min, maxExclusive) (voxel coordinates).
    virtual void worldEdited(const voxel::VoxelWorld& world, Int3 min, Int3 maxExclusive) = 0;
    // Linear radiance, camera.width() x camera.height(); appends its passes to `passes`.
    virtual Result<Image> render(const voxel::VoxelWorld& world, const voxel::Camera& camera,
                                 const voxel::ShadeOptions& shading,
                                 std::vector<PassTime>& passes) = 0;
    // The same with rays through (x + 0.5 + jitter.x, y + 0.5 + jitter.y), for the temporal
    // upscaler. Sources that cannot offset their rays (the GPU) render unjittered.
    virtual Result<Image> renderJittered(const voxel::VoxelWorld& world,
                                         const voxel::Camera& camera,
                                         const voxel::ShadeOptions& shading, Vec2d jitter,
                                         std::vector<PassTime>& passes) {
        (void)jitter;
        return render(world, camera, shading, passes);
    }
};

// The CPU DDA ray caster (luxel::voxel::render), rows in parallel.
std::unique_ptr<VoxelFrameSource> makeCpuVoxelFrameSource(voxel::TextureSet textures = {});

// The GPU ray caster on `device` (index or part of a name; empty: the best device). With
// `hardwareOnly`, software devices (lavapipe: slower than the CPU path) are refused. Fails with
// the reason when there is no usable device or the world does not fit in its memory.
Result<std::unique_ptr<VoxelFrameSource>> makeGpuVoxelFrameSource(const std::string& device,
                                                                  bool hardwareOnly,
                                                                  const voxel::VoxelWorld& world,
                                                                  voxel::TextureSet textures);

}  // namespace luxel::viewer
