// The voxel ray caster on the GPU (Vulkan compute, src/gpu/shaders/voxel/): the same traversal
// (the shared header src/gpu/shaders/shared/voxel_dda.h), cutout textures and shading as
// render() in shading.h, in float instead of double, so images agree with the CPU except at rare
// pixels where a ray passes within float rounding of a voxel edge (tests/gpu/voxel_gpu_test.cpp
// bounds them).
//
// The world is uploaded once in VoxelWorld's chunked layout with per-chunk solid counts, brick
// occupancy masks and the directional brick reach (the CPU's jumps); edits are re-uploaded chunk by
// chunk with updateRegion.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::gpu {
class Buffer;
class Context;
struct PassTiming;
}  // namespace luxel::gpu

namespace luxel::voxel {

// Device memory for a world of this size and chunk size, its textures, and one output image of
// width x height (with placeholders for the sun visibility arrays).
std::uint64_t estimateVoxelGpuMemory(Int3 size, int chunkSize, const TextureSet* textures,
                                     int width, int height);
// Device memory of the sun visibility arrays (moment map, distance field, light levels) physical
// lighting with these settings uploads for a world of this size, on top of the above.
std::uint64_t estimateVoxelShadowGpuMemory(Int3 size, const ShadowSettings& settings);

// Bytes a VoxelGpuRenderer has sent to the device since create, by kind: after create, a new
// camera sends only the parameters, the same camera and options nothing, and updateRegion the
// chunks it touches with every chunk's count, brick mask and reach (tests check this).
struct VoxelGpuUploads {
    std::uint64_t world = 0;       // voxels, solid counts per chunk, brick masks and reach
    std::uint64_t textures = 0;    // texture table, texels and mip chains, sRGB table
    std::uint64_t materials = 0;   // the material table, when it changed
    std::uint64_t parameters = 0;  // camera, light and options, when they changed
    std::uint64_t shadows = 0;     // sun visibility arrays
    std::uint64_t emitters = 0;    // light from emissive voxels: the faces and the grid's lists
    std::uint64_t rays = 0;        // castRays batches
};

class VoxelGpuRenderer {
  public:
    // Uploads the world and textures. Refuses, with the numbers, when the estimate (for a
    // 1920x1080 image) exceeds `memoryBudget` bytes (0: the device's memory). The world and
    // textures must outlive the renderer: physical lighting builds its sun visibility from them.
    static Result<VoxelGpuRenderer> create(gpu::Context& context, const VoxelWorld& world,
                                           const TextureSet* textures = nullptr,
                                           std::uint64_t memoryBudget = 0);
    VoxelGpuRenderer(VoxelGpuRenderer&&) noexcept;
    VoxelGpuRenderer& operator=(VoxelGpuRenderer&&) noexcept;
    ~VoxelGpuRenderer();

    // Re-uploads the chunks overlapping [min, maxExclusive) (clipped to the world) and every
    // chunk's solid count, after edits to `world` (the world given to create, same size). The
    // sun visibility arrays are rebuilt at the next render that needs them.
    Status updateRegion(const VoxelWorld& world, Int3 min, Int3 maxExclusive);

    // Linear RGB image, as render(world, camera, options, textures). options.materialReflectivity
    // (a CPU callback) is refused; per-texture reflectivity works. Physical lighting with a
    // shadow method other than Hard builds options.shadowSettings' SunVisibility on the CPU (or
    // takes options.sunVisibility) and uploads its arrays, kept until the sun, its radius or the
    // settings change; Exact (no GPU twin) is refused. `timings` receives the upload, dispatch
    // (GPU timestamps) and download times.
    Result<Image> render(const Camera& camera, const ShadeOptions& options,
                         std::vector<gpu::PassTiming>* timings = nullptr);

    // The GPU twin of castRays (dda.h): the same traversal, in float, one invocation per ray.
    // Rays are rounded to float; t, point and the face coordinates come back in float.
    Result<std::vector<Hit>> castRays(std::span<const Ray> rays, double tMax = kInfinity,
                                      int stepCap = 0, ChunkSkip skip = ChunkSkip::Enabled,
                                      std::vector<gpu::PassTiming>* timings = nullptr);

    // For other passes over this world that run the ray caster's shader code (the GPU path
    // tracer, path_trace_gpu.h): uploads what render() would for this camera and options (only
    // what changed) and returns the buffers voxel_render binds at 0..14
    // (src/gpu/shaders/shared/voxel_layout.h), valid until the next call to bindings, render or
    // updateRegion. No image is allocated: binding 6 is the parameters buffer, as 10 is.
    Result<std::vector<gpu::Buffer*>> bindings(const Camera& camera, const ShadeOptions& options);

    // Bytes of device memory held now.
    std::uint64_t deviceBytes() const;
    // What has been sent to the device since create.
    const VoxelGpuUploads& uploads() const;
    // The version of the world on the device: 1 after create, +1 for every updateRegion that
    // re-sent chunks (passes that derive data from the world, such as the path tracer's
    // emitters, compare it).
    std::uint64_t worldGeneration() const;

  private:
    struct State;
    explicit VoxelGpuRenderer(std::unique_ptr<State> state);
    // The parameters and materials for this camera and options, and with `image` the output
    // buffer for its pixels.
    Status prepareRender(const Camera& camera, const ShadeOptions& options, bool image);
    std::vector<gpu::Buffer*> renderBuffers() const;
    std::unique_ptr<State> state_;
};

}  // namespace luxel::voxel
