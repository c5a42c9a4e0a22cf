// The voxel radiance cascades' lighting passes on the GPU (Vulkan compute): the same passes as
// RadianceCascades::iterate (its CPU reference), reading the segment codes the CPU found once
// (docs/algorithms/voxel-radiance-cascades.md §4.3). The picture stays on the CPU: download()
// hands the faces' irradiance back to the RadianceCascades it was made from.
#pragma once

#include <memory>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/gpu/fwd.h"
#include "luxel/voxel/radiance_cascades.h"

namespace luxel::voxel {

class RadianceCascadesGpu {
  public:
    // Uploads the codes, corners, bins and the faces' light of `cascades`, which must outlive
    // this object. Fails (naming why) when the device has no room or no shaders.
    static Result<RadianceCascadesGpu> create(gpu::Context& context, RadianceCascades& cascades);
    RadianceCascadesGpu(RadianceCascadesGpu&&) noexcept;
    RadianceCascadesGpu& operator=(RadianceCascadesGpu&&) noexcept;
    ~RadianceCascadesGpu();

    // The faces' light again after RadianceCascades::setLight (sun, sky, materials). Fails when
    // setLight changed the glass's materials (the segments through glass were cast again: create
    // the GPU passes anew).
    Status uploadLight();
    // `passes` lighting passes in one submission; returns the GPU time of the last, in ms.
    Result<double> iterate(int passes = 1);
    // The faces' irradiance into the CPU object (for render() and indirectIrradiance()).
    Status download();
    // RadianceCascades::solve on the GPU: passes until the options' bounces are done or a pass
    // changes the faces' total irradiance by less than the tolerance (measured after each pass,
    // as the CPU does), then download(). Returns the passes run.
    Result<int> solve();

    struct Impl;

  private:
    explicit RadianceCascadesGpu(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// renderRadianceCascades (radiance_cascades.h) with the lighting passes on `context`; the build
// and the picture stay on the CPU.
Result<CascadeImage> renderRadianceCascadesGpu(gpu::Context& context, const VoxelWorld& world,
                                               const Camera& camera, const ShadeOptions& shading,
                                               const CascadeOptions& options = {},
                                               const TextureSet* textures = nullptr);

}  // namespace luxel::voxel
