// `luxel bench SCENE.json` for voxel scenes: best-of-N frame times of the full shading (primary,
// shadow and reflection rays) at one or more image sizes, on the CPU or the GPU; on the GPU the
// dispatch time from timestamps is printed next to the wall time of render().
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {

int benchVoxelScene(const VoxelBenchRequest& request, voxel::VoxelScene loaded) {
    voxel::VoxelScene* scene = &loaded;
    auto sizes = benchSizes(request, scene->camera);
    if (!sizes) return reportError(sizes.error());
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<voxel::VoxelGpuRenderer> renderer;
    if (request.backend == gpu::Backend::Gpu) {
        auto opened = openBenchGpu(request.device);
        if (!opened) return reportError(opened.error());
        context = std::move(*opened);
        auto uploaded = voxel::VoxelGpuRenderer::create(*context, scene->world, &scene->textures);
        if (!uploaded) return reportError(uploaded.error());
        renderer = std::make_unique<voxel::VoxelGpuRenderer>(std::move(*uploaded));
    }
    const voxel::ShadeOptions& shading = scene->shading;
    std::printf("%s, voxel ray casting on the %s (%d reflections, shadows %s), best of %d\n",
                request.scene.c_str(), gpu::backendName(request.backend), shading.maxReflections,
                shading.shadows ? "on" : "off", request.repeat);
    return benchFrames(request, *sizes, scene->camera, renderer != nullptr,
                       [&](const voxel::Camera& camera, std::vector<gpu::PassTiming>* timings) {
                           Result<Image> image =
                               renderer ? renderer->render(camera, shading, timings)
                                        : Result<Image>(voxel::render(scene->world, camera, shading,
                                                                      &scene->textures));
                           return image ? Status(Ok{}) : Status(image.error());
                       });
}

}  // namespace luxel::cli
