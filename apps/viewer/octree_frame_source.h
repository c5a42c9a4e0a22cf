// The backend seam of octree mode: renders the octree for a camera and render options, on the
// CPU (octree::renderOctree) or the GPU (octree::OctreeGpu, the tree uploaded once), the two
// twins of one pixel kernel (docs/algorithms/sparse-voxel-octree.md §5).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frame.h"
#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_render.h"
#include "luxel/voxel/camera.h"

namespace luxel::viewer {

class OctreeFrameSource {
  public:
    virtual ~OctreeFrameSource() = default;
    virtual std::string backend() const = 0;  // "cpu" or "gpu"
    virtual std::string device() const = 0;   // shown in the overlay
    // A hardware GPU, fast enough to render the full window (lavapipe and the CPU are not).
    virtual bool hardwareGpu() const = 0;
    // Linear radiance, camera.width() x camera.height(); appends its passes to `passes`.
    virtual Result<Image> render(const octree::Octree& tree, const voxel::Camera& camera,
                                 const octree::OctreeRenderOptions& options,
                                 std::vector<PassTime>& passes) = 0;
};

// renderOctree, rows in parallel.
std::unique_ptr<OctreeFrameSource> makeCpuOctreeFrameSource();

// OctreeGpu on `device` (index or part of a name; empty: the best device). With `hardwareOnly`,
// software devices (lavapipe: slower than the CPU path) are refused. Fails with the reason when
// there is no usable device or the tree does not fit in its memory.
Result<std::unique_ptr<OctreeFrameSource>> makeGpuOctreeFrameSource(const std::string& device,
                                                                    bool hardwareOnly,
                                                                    const octree::Octree& tree);

}  // namespace luxel::viewer
