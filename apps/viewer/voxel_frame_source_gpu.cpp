// VoxelFrameSource on the GPU: the world is uploaded once; edits re-upload the chunks they touch
// before the next frame, and the overlay gets the dispatch times from GPU timestamps.
#include <utility>

#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/voxel_gpu.h"
#include "voxel_frame_source.h"

namespace luxel::viewer {
namespace {

class GpuVoxelFrameSource final : public VoxelFrameSource {
  public:
    GpuVoxelFrameSource(std::unique_ptr<gpu::Context> context, voxel::TextureSet textures)
        : context_(std::move(context)), textures_(std::move(textures)) {}

    Status upload(const voxel::VoxelWorld& world) {
        auto renderer = voxel::VoxelGpuRenderer::create(*context_, world, &textures_);
        if (!renderer) return renderer.error();
        renderer_ = std::make_unique<voxel::VoxelGpuRenderer>(std::move(*renderer));
        return Ok{};
    }

    std::string backend() const override { return "gpu"; }
    std::string device() const override { return context_->device().name; }
    bool hardwareGpu() const override { return gpu::autoUsesDevice(context_->device()); }
    const voxel::TextureSet& textures() const override { return textures_; }
    GpuWorld gpuWorld() override { return {context_.get(), renderer_.get()}; }
    void worldEdited(const voxel::VoxelWorld& world, Int3 min, Int3 maxExclusive) override {
        // A failed upload leaves the old chunk on the GPU; the next render reports nothing wrong
        // but shows the edit late, so keep the message for the overlay.
        if (Status s = renderer_->updateRegion(world, min, maxExclusive); !s) {
            pendingError_ = s.error().message();
        }
    }
    Result<Image> render(const voxel::VoxelWorld&, const voxel::Camera& camera,
                         const voxel::ShadeOptions& shading,
                         std::vector<PassTime>& passes) override {
        if (!pendingError_.empty()) return Error(std::exchange(pendingError_, {}));
        std::vector<gpu::PassTiming> timings;
        auto image = renderer_->render(camera, shading, &timings);
        for (const gpu::PassTiming& t : timings) passes.push_back({t.name, t.milliseconds});
        return image;
    }

  private:
    std::unique_ptr<gpu::Context> context_;
    voxel::TextureSet textures_;
    std::unique_ptr<voxel::VoxelGpuRenderer> renderer_;
    std::string pendingError_;
};

}  // namespace

Result<std::unique_ptr<VoxelFrameSource>> makeGpuVoxelFrameSource(const std::string& device,
                                                                  bool hardwareOnly,
                                                                  const voxel::VoxelWorld& world,
                                                                  voxel::TextureSet textures) {
    auto context = gpu::Context::create({device, false});
    if (!context) return context.error();
    if (hardwareOnly && !gpu::autoUsesDevice((*context)->device())) {
        return Error("only a software Vulkan device (" + (*context)->device().name +
                     "), slower than the CPU path");
    }
    auto source = std::make_unique<GpuVoxelFrameSource>(std::move(*context), std::move(textures));
    if (Status s = source->upload(world); !s) return s.error();
    return std::unique_ptr<VoxelFrameSource>(std::move(source));
}

}  // namespace luxel::viewer
