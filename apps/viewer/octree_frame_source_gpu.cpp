// OctreeFrameSource on the GPU: the tree is uploaded once (octree mode does not edit it), and the
// overlay gets the dispatch times from GPU timestamps.
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree_gpu.h"
#include "octree_frame_source.h"

namespace luxel::viewer {
namespace {

class GpuOctreeFrameSource final : public OctreeFrameSource {
  public:
    GpuOctreeFrameSource(std::unique_ptr<gpu::Context> context, octree::OctreeGpu tree)
        : context_(std::move(context)), tree_(std::move(tree)) {}

    std::string backend() const override { return "gpu"; }
    std::string device() const override { return context_->device().name; }
    bool hardwareGpu() const override { return gpu::autoUsesDevice(context_->device()); }
    Result<Image> render(const octree::Octree&, const voxel::Camera& camera,
                         const octree::OctreeRenderOptions& options,
                         std::vector<PassTime>& passes) override {
        std::vector<gpu::PassTiming> timings;
        auto image = tree_.render(camera, options, &timings);
        for (const gpu::PassTiming& t : timings) passes.push_back({t.name, t.milliseconds});
        return image;
    }

  private:
    std::unique_ptr<gpu::Context> context_;  // outlives tree_ (members die in reverse order)
    octree::OctreeGpu tree_;
};

}  // namespace

Result<std::unique_ptr<OctreeFrameSource>> makeGpuOctreeFrameSource(const std::string& device,
                                                                    bool hardwareOnly,
                                                                    const octree::Octree& tree) {
    auto context = gpu::Context::create({device, false});
    if (!context) return context.error();
    if (hardwareOnly && !gpu::autoUsesDevice((*context)->device())) {
        return Error("only a software Vulkan device (" + (*context)->device().name +
                     "), slower than the CPU path");
    }
    auto uploaded = octree::OctreeGpu::create(**context, tree);
    if (!uploaded) return uploaded.error();
    return std::unique_ptr<OctreeFrameSource>(
        std::make_unique<GpuOctreeFrameSource>(std::move(*context), std::move(*uploaded)));
}

}  // namespace luxel::viewer
