// `luxel render` for voxel scenes: DDA ray casting with shading, shadows and reflections, on the
// CPU or (--backend) the GPU.
#include <cstdio>
#include <memory>
#include <string>

#include "commands/command.h"
#include "luxel/core/image_io.h"
#include "luxel/core/timer.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

Result<Image> renderOnGpu(gpu::Context& context, const voxel::VoxelScene& scene) {
    auto renderer = voxel::VoxelGpuRenderer::create(context, scene.world, &scene.textures);
    if (!renderer) return renderer.error();
    return renderer->render(scene.camera, scene.shading);
}

}  // namespace

int renderVoxelScene(const VoxelRenderRequest& request, voxel::VoxelScene loaded) {
    voxel::VoxelScene* scene = &loaded;
    const double loadSeconds = request.loadSeconds;
    if (request.samples != 0) {
        if (request.samples < 1 || request.samples > voxel::kMaxSamplesPerPixel) {
            return reportError(
                Error("--samples must be in 1.." + std::to_string(voxel::kMaxSamplesPerPixel)));
        }
        scene->shading.samplesPerPixel = request.samples;
    }
    if (!request.filter.empty()) {
        const auto filter = voxel::parseTextureFilter(request.filter);
        if (!filter) {
            return reportError(Error("--filter '" + request.filter +
                                     "' is not nearest, trilinear or anisotropic"));
        }
        scene->shading.textureFilter = *filter;
    }
    auto context = chooseGpuBackend(request.backend, request.device, request.quiet);
    if (!context) return reportError(context.error());
    Stopwatch renderTime;
    Image radiance;
    if (*context) {
        auto image = renderOnGpu(**context, *scene);
        if (!image) return reportError(image.error());
        radiance = std::move(*image);
    } else {
        radiance = voxel::render(scene->world, scene->camera, scene->shading, &scene->textures);
    }
    const double renderSeconds = renderTime.seconds();
    // EXR keeps linear radiance; PNG gets the display transform.
    const Image out =
        hasExtension(request.out, ".png") ? toneMap(radiance, request.tone) : radiance;
    if (Status s = writeImage(request.out, out); !s) return reportError(s.error());
    if (!request.png.empty()) {
        if (Status s = writePng(request.png, toneMap(radiance, request.tone)); !s) {
            return reportError(s.error());
        }
    }
    if (request.stats) std::printf("stats solve_seconds=%.6f\n", renderSeconds);
    if (!request.quiet) {
        const Int3 s = scene->world.size();
        const double pixels = static_cast<double>(radiance.width()) * radiance.height();
        std::printf("%s: voxel world %dx%dx%d (%llu solid), image %dx%d, %d reflections, %s\n",
                    request.scene.c_str(), s.x, s.y, s.z,
                    static_cast<unsigned long long>(scene->world.solidCount()), radiance.width(),
                    radiance.height(), scene->shading.maxReflections,
                    *context ? ("gpu: " + (**context).device().name).c_str() : "cpu");
        std::printf("  %d samples per pixel, %s textures\n", voxel::samplesPerPixel(scene->shading),
                    voxel::textureFilterName(scene->shading.textureFilter));
        std::printf("  world %.3f s, render %.3f s incl. upload (%.2f Mpixel/s)\n", loadSeconds,
                    renderSeconds, pixels / renderSeconds * 1e-6);
        std::printf("  wrote %s%s%s\n", request.out.c_str(), request.png.empty() ? "" : ", ",
                    request.png.c_str());
    }
    return 0;
}

}  // namespace luxel::cli
