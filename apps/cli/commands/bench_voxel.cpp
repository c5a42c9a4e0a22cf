// `luxel bench SCENE.json` for voxel scenes: best-of-N frame times of the full shading (primary,
// shadow and reflection rays) at one or more image sizes, on the CPU or the GPU; on the GPU the
// dispatch time from timestamps is printed next to the wall time of render().
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include "commands/command.h"
#include "luxel/core/image_size.h"
#include "luxel/core/timer.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

// The scene's view at another image size.
Result<voxel::Camera> resized(const voxel::Camera& camera, int width, int height) {
    return voxel::Camera::lookAt(camera.position(), camera.position() + camera.forward(),
                                 camera.fovYDegrees(), width, height);
}

}  // namespace

int benchVoxelScene(const VoxelBenchRequest& request, voxel::VoxelScene loaded) {
    if (request.repeat < 1) return reportError(Error("--repeat must be at least 1"));
    voxel::VoxelScene* scene = &loaded;
    std::vector<ImageSize> sizes{{scene->camera.width(), scene->camera.height()}};
    if (!request.sizes.empty()) {
        auto parsed = parseImageSizeList(request.sizes, "--sizes");
        if (!parsed) return reportError(parsed.error());
        sizes = *parsed;
    }
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
    std::printf("%11s %10s %9s%s\n", "size", "ms", "Mpix/s", renderer ? "  dispatch ms" : "");
    for (const auto& [width, height] : sizes) {
        auto camera = resized(scene->camera, width, height);
        if (!camera) return reportError(camera.error());
        double best = 1e300, bestDispatch = 0;
        for (int r = 0; r < request.repeat + (renderer ? 1 : 0); ++r) {  // GPU: one warm-up run
            std::vector<gpu::PassTiming> timings;
            Stopwatch clock;
            Result<Image> image = renderer ? renderer->render(*camera, shading, &timings)
                                           : Result<Image>(voxel::render(
                                                 scene->world, *camera, shading, &scene->textures));
            const double ms = clock.milliseconds();
            if (!image) return reportError(image.error());
            if (renderer && r == 0) continue;
            if (ms < best) {
                best = ms;
                bestDispatch = 0;
                for (const gpu::PassTiming& t : timings) {
                    if (t.name.find("upload") == std::string::npos &&
                        t.name.find("download") == std::string::npos) {
                        bestDispatch += t.milliseconds;
                    }
                }
            }
        }
        const std::string label = std::to_string(width) + "x" + std::to_string(height);
        std::printf("%11s %10.2f %9.2f", label.c_str(), best,
                    static_cast<double>(width) * height / best * 1e-3);
        if (renderer) std::printf("  %11.2f", bestDispatch);
        std::printf("\n");
    }
    return 0;
}

}  // namespace luxel::cli
