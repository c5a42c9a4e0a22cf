// VoxelFrameSource on the CPU: the library's ray caster reads the world directly, so edits need
// no upload.
#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "luxel/post/voxel_frames.h"
#include "luxel/voxel/render_image.h"
#include "voxel_frame_source.h"

namespace luxel::viewer {
namespace {

class CpuVoxelFrameSource final : public VoxelFrameSource {
  public:
    explicit CpuVoxelFrameSource(voxel::TextureSet textures) : textures_(std::move(textures)) {}
    std::string backend() const override { return "cpu"; }
    std::string device() const override {
        return "CPU, " + std::to_string(hardwareThreads()) + " threads";
    }
    bool hardwareGpu() const override { return false; }
    const voxel::TextureSet& textures() const override { return textures_; }
    void worldEdited(const voxel::VoxelWorld&, Int3, Int3) override {}
    Result<Image> render(const voxel::VoxelWorld& world, const voxel::Camera& camera,
                         const voxel::ShadeOptions& shading,
                         std::vector<PassTime>& passes) override {
        Stopwatch clock;
        Image image = voxel::render(world, camera, shading, &textures_);
        passes.push_back({"ray cast + shade", clock.milliseconds()});
        return image;
    }
    Result<Image> renderJittered(const voxel::VoxelWorld& world, const voxel::Camera& camera,
                                 const voxel::ShadeOptions& shading, Vec2d jitter,
                                 std::vector<PassTime>& passes) override {
        Stopwatch clock;
        Image image = post::renderJittered(world, camera, shading, &textures_, jitter);
        passes.push_back({"ray cast + shade (jittered)", clock.milliseconds()});
        return image;
    }

  private:
    voxel::TextureSet textures_;
};

}  // namespace

std::unique_ptr<VoxelFrameSource> makeCpuVoxelFrameSource(voxel::TextureSet textures) {
    return std::make_unique<CpuVoxelFrameSource>(std::move(textures));
}

}  // namespace luxel::viewer
