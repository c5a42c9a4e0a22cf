// OctreeFrameSource on the CPU: renderOctree reads the tree directly. The volume mode's light
// cache is kept between frames and refilled only when the light, the opacity or the tree changes,
// so orbiting a scattering volume costs the view rays alone.
#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "luxel/octree/octree_light_cache.h"
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
        const bool refill = !lightCache_.matches(tree, options);
        auto image = octree::renderOctree(tree, camera, options, &lightCache_);
        passes.push_back({refill ? "octree render (light cache filled)" : "octree render",
                          clock.milliseconds()});
        return image;
    }

  private:
    octree::OctreeLightCache lightCache_;
};

}  // namespace

std::unique_ptr<OctreeFrameSource> makeCpuOctreeFrameSource() {
    return std::make_unique<CpuOctreeFrameSource>();
}

}  // namespace luxel::viewer
