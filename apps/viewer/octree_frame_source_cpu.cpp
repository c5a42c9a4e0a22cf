// OctreeFrameSource on the CPU: renderOctree reads the tree directly.
#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "octree_frame_source.h"

namespace luxel::viewer {
namespace {

class CpuOctreeFrameSource final : public OctreeFrameSource {
  public:
    std::string backend() const override { return "cpu"; }
    std::string device() const override {
        return "CPU, " + std::to_string(hardwareThreads()) + " threads";
    }
    bool hardwareGpu() const override { return false; }
    Result<Image> render(const octree::Octree& tree, const voxel::Camera& camera,
                         const octree::OctreeRenderOptions& options,
                         std::vector<PassTime>& passes) override {
        Stopwatch clock;
        auto image = octree::renderOctree(tree, camera, options);
        passes.push_back({"octree render", clock.milliseconds()});
        return image;
    }
};

}  // namespace

std::unique_ptr<OctreeFrameSource> makeCpuOctreeFrameSource() {
    return std::make_unique<CpuOctreeFrameSource>();
}

}  // namespace luxel::viewer
