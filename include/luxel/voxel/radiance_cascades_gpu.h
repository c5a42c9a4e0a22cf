// The voxel radiance cascades on the GPU (Vulkan compute): the same lighting passes as
// RadianceCascades::iterate (its CPU reference), reading the segment codes the CPU found once,
// and the same picture as RadianceCascades::render, drawn from the faces' irradiance the passes
// left on the device (docs/algorithms/voxel-radiance-cascades.md §4.3). download() hands the
// faces' irradiance back to the RadianceCascades it was made from.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/gpu/fwd.h"
#include "luxel/voxel/radiance_cascades.h"

namespace luxel::voxel {

class VoxelGpuRenderer;

class RadianceCascadesGpu {
  public:
    // Uploads the codes, corners, bins and the faces' light of `cascades`, which must outlive
    // this object. Fails (naming why) when the device has no room or no shaders.
    static Result<RadianceCascadesGpu> create(gpu::Context& context, RadianceCascades& cascades);
    RadianceCascadesGpu(RadianceCascadesGpu&&) noexcept;
    RadianceCascadesGpu& operator=(RadianceCascadesGpu&&) noexcept;
    ~RadianceCascadesGpu();

    // The faces' light again after RadianceCascades::setLight (sun, sky, materials). Fails when
    // setLight changed what passes glass (the faces under glass and the segments were built
    // again: create the GPU passes anew; iterate and download fail then too).
    Status uploadLight();
    // `passes` lighting passes in one submission; returns the GPU time of the last, in ms.
    Result<double> iterate(int passes = 1);
    // The faces' irradiance into the CPU object (for its render() and indirectIrradiance()).
    Status download();
    // One lighting pass, then download(); returns the pass's relative change of the faces'
    // irradiance, as RadianceCascades::iterate does (the viewer's one reflection per frame).
    Result<double> iterateOnce();
    // RadianceCascades::render on the GPU: the same rays and random numbers, in float, from the
    // faces' irradiance on the device (no download). The first call uploads the world, its
    // textures and the faces' table. Fails (naming why) when the image has more than
    // kMaxPathPixels pixels or the world's upload, the faces' table and the image need more
    // than `memoryBudget` bytes (0: the device's memory). `gpuMilliseconds` receives the
    // dispatches' GPU time (the first pass and the adaptive one), `refinedPixels` the pixels the
    // adaptive pass drew again (the CPU's rule on the downloaded first pass).
    Result<Image> render(const Camera& camera, double* gpuMilliseconds = nullptr,
                         std::uint64_t memoryBudget = 0, int* refinedPixels = nullptr);
    // Draws the picture over `world`, an upload of the cascades' own world and textures on this
    // object's context that outlives it (the viewer's ray caster's), instead of uploading a
    // copy of its own on the first render; the memory check then counts only the faces' table
    // and the image. Takes effect at the next render.
    void useUploadedWorld(VoxelGpuRenderer& world);
    // RadianceCascades::solve on the GPU: passes until the options' bounces are done or a pass
    // changes the faces' total irradiance by less than the tolerance (measured after each pass,
    // as the CPU does), then download(). Returns the passes run.
    Result<int> solve();

    struct Impl;

  private:
    explicit RadianceCascadesGpu(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// renderRadianceCascades (radiance_cascades.h) with the lighting passes and the picture on
// `context`; the build stays on the CPU. When the GPU cannot draw the picture (no room on the
// device), the CPU draws it and `note` (when given) receives why; it is left empty otherwise.
Result<CascadeImage> renderRadianceCascadesGpu(gpu::Context& context, const VoxelWorld& world,
                                               const Camera& camera, const ShadeOptions& shading,
                                               const CascadeOptions& options = {},
                                               const TextureSet* textures = nullptr,
                                               std::string* note = nullptr);

}  // namespace luxel::voxel
