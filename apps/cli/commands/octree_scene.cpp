// `luxel render`, `info` and `bench` on octree scenes ("type": "octree"): the exact octree
// traversal with the surface, volume and additive modes, on the CPU or (--backend) the GPU.
#include <cstdio>
#include <memory>
#include <vector>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "commands/render_outputs.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree_gpu.h"
#include "luxel/octree/octree_render.h"
#include "luxel/post/finish.h"
#include "luxel/post/upscale.h"
#include "luxel/post/voxel_frames.h"

namespace luxel::cli {
namespace {

void printStats(const octree::OctreeStats& s) {
    std::printf("  octree             depth %d (%d^3), %llu octants (%llu if unshared), %s\n",
                s.depth, 1 << s.depth, static_cast<unsigned long long>(s.octants),
                static_cast<unsigned long long>(s.expandedOctants),
                formatBytes(s.geometryBytes).c_str());
    std::printf("  voxels             %llu solid of %.3g\n",
                static_cast<unsigned long long>(s.solidVoxels), static_cast<double>(s.totalVoxels));
    std::printf("  bits per voxel     %.4f per solid voxel, %.3g per voxel (geometry)\n",
                s.bitsPerSolidVoxel, s.bitsPerVoxel);
    if (s.attributeBytes > 0) {
        std::printf("  colours            %s (attributes, separate from the geometry), %s\n",
                    formatBytes(s.attributeBytes).c_str(), octree::attributeLayoutName(s.layout));
    }
    if (s.attributeIndexBytes > 0) {
        std::printf("  attribute index    %s (leaf counts, one per octant)\n",
                    formatBytes(s.attributeIndexBytes).c_str());
    }
}

}  // namespace

int renderOctreeScene(const VoxelRenderRequest& request, scene::OctreeScene loaded) {
    scene::OctreeScene* scene = &loaded;
    auto context = chooseGpuBackend(request.backend, request.device, request.quiet);
    if (!context) return reportError(context.error());
    // Octree scenes have no "post" section: the flags alone.
    const post::PostOptions post = applyPostFlags(post::PostOptions{}, request.post);
    const int width = scene->camera.width(), height = scene->camera.height();
    const voxel::Camera camera =
        post.internalScale < 1.0f
            ? post::resizedCamera(scene->camera, post::internalSide(width, post.internalScale),
                                  post::internalSide(height, post.internalScale))
            : scene->camera;
    // Refuse before the first frame buffer (`luxel info` reports the same estimate).
    if (Status s =
            checkRenderMemory(width, height, frameBytes(width, height, post, *context != nullptr));
        !s) {
        return reportError(s.error());
    }
    Stopwatch renderTime;
    Result<Image> radiance = Image();
    if (*context) {
        auto uploaded = octree::OctreeGpu::create(**context, scene->tree);
        if (!uploaded) return reportError(uploaded.error());
        radiance = uploaded->render(camera, scene->render);
    } else {
        radiance = octree::renderOctree(scene->tree, camera, scene->render);
    }
    if (!radiance) return reportError(radiance.error());
    const double renderSeconds = renderTime.seconds();
    radiance = post::processInternal(*radiance, width, height, post);
    // --out and --png change together or not at all; both carry the provenance.
    RenderImages images;
    images.out = request.out;
    images.png = request.png;
    images.linear = &*radiance;
    images.linearName = "radiance";
    images.displayHdr = &*radiance;
    images.tone = post.tone;
    images.autoExposure = request.autoExposure;
    images.quiet = request.quiet;
    images.metadata = octreeMetadata(request.scene, scene->source, scene->render, post, width,
                                     height, context->get(), renderSeconds);
    if (Status s = writeRenderImages(std::move(images)); !s) return reportError(s.error());
    if (request.stats) std::printf("stats solve_seconds=%.6f\n", renderSeconds);
    if (!request.quiet) {
        const double pixels = static_cast<double>(radiance->width()) * radiance->height();
        std::printf("%s: octree (%s), %s mode, image %dx%d, %s\n", request.scene.c_str(),
                    scene->source.c_str(), octree::octreeModeName(scene->render.mode),
                    radiance->width(), radiance->height(),
                    *context ? ("gpu: " + (**context).device().name).c_str() : "cpu");
        std::printf("  build %.3f s, render %.3f s incl. upload (%.2f Mpixel/s)\n",
                    scene->buildSeconds, renderSeconds, pixels / renderSeconds * 1e-6);
        std::printf("  wrote %s%s%s\n", request.out.c_str(),
                    request.out.empty() || request.png.empty() ? "" : ", ", request.png.c_str());
    }
    return 0;
}

int infoOctreeScene(const scene::OctreeScene& scene) {
    std::printf("%s\n", scene.sourcePath.c_str());
    std::printf("  source             %s (built in %.3f s)\n", scene.source.c_str(),
                scene.buildSeconds);
    printStats(octree::measure(scene.tree));
    const Vec3d p = scene.camera.position(), f = scene.camera.forward();
    std::printf("  camera             at (%g, %g, %g) looking along (%.3f, %.3f, %.3f), fov %g\n",
                p.x, p.y, p.z, f.x, f.y, f.z, scene.camera.fovYDegrees());
    std::printf("  image              %dx%d, %s mode\n", scene.camera.width(),
                scene.camera.height(), octree::octreeModeName(scene.render.mode));
    // What `luxel render` checks on the CPU path (octree scenes have no "post" section).
    const int w = scene.camera.width(), h = scene.camera.height();
    const std::uint64_t frame = frameBytes(w, h, post::PostOptions{}, false);
    std::printf("  memory (cpu)       %s for the frame (available %s)\n",
                formatBytes(frame).c_str(), formatBytes(availableMemoryBytes()).c_str());
    if (Status s = checkRenderMemory(w, h, frame); !s) return reportError(s.error());
    return 0;
}

int benchOctreeScene(const VoxelBenchRequest& request, scene::OctreeScene loaded) {
    scene::OctreeScene* scene = &loaded;
    auto sizes = benchSizes(request, scene->camera);
    if (!sizes) return reportError(sizes.error());
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<octree::OctreeGpu> gpuTree;
    if (request.backend == gpu::Backend::Gpu) {
        auto opened = openBenchGpu(request.device);
        if (!opened) return reportError(opened.error());
        context = std::move(*opened);
        auto uploaded = octree::OctreeGpu::create(*context, scene->tree);
        if (!uploaded) return reportError(uploaded.error());
        gpuTree = std::make_unique<octree::OctreeGpu>(std::move(*uploaded));
    }
    std::printf("%s, octree %s mode on the %s, best of %d\n", request.scene.c_str(),
                octree::octreeModeName(scene->render.mode), gpu::backendName(request.backend),
                request.repeat);
    return benchFrames(request, *sizes, scene->camera, gpuTree != nullptr,
                       [&](const voxel::Camera& camera, std::vector<gpu::PassTiming>* timings) {
                           auto image =
                               gpuTree ? gpuTree->render(camera, scene->render, timings)
                                       : octree::renderOctree(scene->tree, camera, scene->render);
                           return image ? Status(Ok{}) : Status(image.error());
                       });
}

}  // namespace luxel::cli
