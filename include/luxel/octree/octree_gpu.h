// The octree on the GPU (Vulkan): the array (and colours) uploaded once, then batches of rays
// cast by the shared traversal kernel (src/gpu/shaders/shared/octree_walk.h) in float, the GPU
// twin of octree::castRays (octree_trace.h), and images rendered by the shared pixel kernel, the
// twin of renderOctree (octree_render.h).
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/octree_trace.h"
#include "luxel/voxel/camera.h"

namespace luxel::octree {

class OctreeGpu {
  public:
    // Uploads a validated tree; refuses, with the numbers, a tree larger than the device memory.
    static Result<OctreeGpu> create(gpu::Context& context, const Octree& tree);
    OctreeGpu(OctreeGpu&&) noexcept;
    OctreeGpu& operator=(OctreeGpu&&) noexcept;
    ~OctreeGpu();

    // Rays are rounded to float; t, point and face coordinates come back in float.
    Result<std::vector<OctreeHit>> castRays(std::span<const voxel::Ray> rays,
                                            const TraceOptions& options = {},
                                            std::vector<gpu::PassTiming>* timings = nullptr);

    // The GPU twin of renderOctree (octree_render.h): the same per-pixel kernel, in float. The
    // light cache of volume scattering is filled by its own pass and kept while the sun
    // direction, the opacity scale and the stride are unchanged.
    Result<Image> render(const voxel::Camera& camera, const OctreeRenderOptions& options,
                         std::vector<gpu::PassTiming>* timings = nullptr);

    // The light cache pass alone (the twin of fillLightCache, octree_light_cache.h): T_sun per
    // corner, empty when the options have no cache.
    Result<std::vector<float>> lightCache(const OctreeRenderOptions& options,
                                          std::vector<gpu::PassTiming>* timings = nullptr);

    std::uint64_t deviceBytes() const;

  private:
    struct State;
    explicit OctreeGpu(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

}  // namespace luxel::octree
