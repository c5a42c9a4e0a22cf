// The tile rendering of the WebGL octree design on the GPU (Vulkan): the tree uploaded once, then
// each frame one dispatch of octree_tiles per scale pass, the GPU twin of renderOctreeTiles
// (octree_tiles.h), in float.
#pragma once

#include <memory>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/octree_tiles.h"
#include "luxel/voxel/camera.h"

namespace luxel::octree {

struct OctreeDeviceArrays;

class OctreeTilesGpu {
  public:
    // Uploads a validated tree; refuses, with the numbers, a tree larger than the device memory.
    static Result<OctreeTilesGpu> create(gpu::Context& context, const Octree& tree);
    // The same over a tree already on the device (src/octree/octree_device_arrays.h), whose
    // buffers it shares: OctreeGpu's tiles mode.
    static Result<OctreeTilesGpu> create(gpu::Context& context, const OctreeDeviceArrays& arrays);
    OctreeTilesGpu(OctreeTilesGpu&&) noexcept;
    OctreeTilesGpu& operator=(OctreeTilesGpu&&) noexcept;
    ~OctreeTilesGpu();

    // One timing per pass ("octree tiles pass k").
    Result<TileRender> render(const voxel::Camera& camera, const OctreeRenderOptions& options,
                              const TileOptions& tiles = {},
                              std::vector<gpu::PassTiming>* timings = nullptr);

  private:
    struct State;
    explicit OctreeTilesGpu(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

}  // namespace luxel::octree
