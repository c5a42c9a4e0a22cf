// `luxel info` on a voxel scene: the world, camera and render options it holds, and the memory
// rendering it needs on the CPU and on the GPU.
#include <cstdio>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "luxel/core/memory.h"
#include "luxel/post/upscale.h"
#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/path_trace_gpu.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {

int infoVoxelScene(const voxel::VoxelScene& loaded) {
    const voxel::VoxelScene* scene = &loaded;
    const voxel::VoxelWorld& world = scene->world;
    const voxel::Camera& camera = scene->camera;
    const voxel::ShadeOptions& shading = scene->shading;
    const Int3 s = world.size();
    std::printf("%s\n", scene->sourcePath.c_str());
    std::printf("  world              %dx%dx%d voxels in chunks of %d, %llu solid\n", s.x, s.y, s.z,
                world.chunkSize(), static_cast<unsigned long long>(world.solidCount()));
    std::printf("  textures           %d (materials %d)\n", scene->textures.size(),
                shading.materials.slotCount());
    std::printf(
        "  lighting           %s\n",
        shading.lighting == voxel::ShadeOptions::Lighting::Physical ? "physical" : "classic");
    const Vec3d p = camera.position(), f = camera.forward();
    std::printf("  camera             at (%g, %g, %g) looking along (%.3f, %.3f, %.3f), fov %g\n",
                p.x, p.y, p.z, f.x, f.y, f.z, camera.fovYDegrees());
    std::printf("  image              %dx%d\n", camera.width(), camera.height());
    const Vec3 sun = shading.sunDirection;
    std::printf("  sun                (%g, %g, %g)\n", sun.x, sun.y, sun.z);
    if (shading.skyModel == voxel::ShadeOptions::SkyModel::Preetham) {
        std::printf("  sky                Preetham clear sky, turbidity %g, zenith luminance %g\n",
                    shading.skyTurbidity, shading.skyZenithLuminance);
    } else {
        const Rgb top = shading.skyTop, horizon = shading.skyHorizon;
        std::printf("  sky                gradient, top (%g, %g, %g), horizon (%g, %g, %g)\n",
                    top.r, top.g, top.b, horizon.r, horizon.g, horizon.b);
    }
    std::printf("  reflections        %d (%s)\n", shading.maxReflections,
                shading.reflectionMode == voxel::ShadeOptions::ReflectionMode::EnergyConserving
                    ? "energy"
                    : "running-average");
    std::printf("  shadows, textures  %s, %s\n", shading.shadows ? "on" : "off",
                shading.textures ? "on" : "off");
    // The ray caster's light from emissive voxels: the faces, their rectangles and the grid's
    // lists a render builds (emitter_light.h; bounded by kMaxEmitterFaces and
    // kMaxEmitterListEntries).
    std::uint64_t lampBytes = 0;
    if (shading.lighting == voxel::ShadeOptions::Lighting::Physical && shading.emitterLight) {
        const voxel::EmitterLights lamps = voxel::EmitterLights::build(world, shading.materials);
        lampBytes = lamps.faces().size() * sizeof(voxel::EmitterFace) +
                    (lamps.cellOffsets().size() + lamps.cellFaces().size()) * sizeof(std::uint32_t);
        std::printf(
            "  lamp light         %d open emissive faces in %d rectangles, %d shadow rays "
            "each, lists %s\n",
            lamps.faceCount(), lamps.emitterCount(), shading.emitterRays,
            formatBytes(lampBytes).c_str());
    } else {
        std::printf("  lamp light         off\n");
    }
    // The world is loaded already; a render then allocates its frames (render_memory.h).
    const std::uint64_t frame = frameBytes(camera.width(), camera.height(), scene->post, false);
    const std::uint64_t worldBytes = voxel::VoxelWorld::bytesFor(s, world.chunkSize());
    std::printf("  memory (cpu)       %s (world %s, frames %s, lamp lists %s; available %s)\n",
                formatBytes(worldBytes + frame + lampBytes).c_str(),
                formatBytes(worldBytes).c_str(), formatBytes(frame).c_str(),
                formatBytes(lampBytes).c_str(), formatBytes(availableMemoryBytes()).c_str());
    std::printf("  memory (gpu)       %s\n",
                formatBytes(voxel::estimateVoxelGpuMemory(s, world.chunkSize(), &scene->textures,
                                                          camera.width(), camera.height()))
                    .c_str());
    // What `luxel render --solver rc` would build (radiance_cascades.h).
    const voxel::CascadeEstimate rc = voxel::estimateCascades(world);
    // Runs through glass are not estimated ahead; the build counts them against the limit and,
    // where they do not fit, doubles the automatic spacing.
    const bool glass = shading.lightPassesMedia();
    std::printf("  cascades (rc)      %s: spacing %d, %d levels, %lld probes, %lld faces%s%s\n",
                formatBytes(rc.bytes).c_str(), rc.spacing, rc.levels,
                static_cast<long long>(rc.probes), static_cast<long long>(rc.faces),
                glass ? ", + runs through glass (checked while building; an automatic spacing "
                        "doubles where they do not fit)"
                      : "",
                rc.fits ? "" : " (over the limit: luxel render --solver rc refuses it)");
    // What `luxel render --solver path` would allocate (path_trace.h, path_trace_gpu.h), at the
    // internal size it traces at; the CPU line says whether render would refuse it.
    const float scale = scene->post.internalScale;
    const int width = scale < 1.0f ? post::internalSide(camera.width(), scale) : camera.width();
    const int height = scale < 1.0f ? post::internalSide(camera.height(), scale) : camera.height();
    const voxel::PathTraceMemory pathCpu = voxel::estimatePathTraceMemory(width, height);
    const std::uint64_t available = availableMemoryBytes();
    std::printf("  path (cpu)         %s: running sums of %dx%d pixels%s\n",
                formatBytes(pathCpu.host).c_str(), width, height,
                available > 0 && frame + pathCpu.host > available
                    ? " (over the limit: luxel render --solver path refuses it)"
                    : "");
    const int emitters = voxel::PathEmitters::find(world, shading.materials).size();
    const voxel::PathTraceMemory pathGpu =
        voxel::estimatePathTraceGpuMemory(world, &scene->textures, width, height, emitters);
    std::printf("  path (gpu)         host %s, device %s (world %s, sums %s, %d emitters %s)\n",
                formatBytes(pathGpu.host).c_str(), formatBytes(pathGpu.device()).c_str(),
                formatBytes(pathGpu.world).c_str(), formatBytes(pathGpu.sums).c_str(), emitters,
                formatBytes(pathGpu.emitters).c_str());
    // The same refusal as `luxel render` on the CPU path.
    if (Status st = checkRenderMemory(camera.width(), camera.height(), frame); !st) {
        return reportError(st.error());
    }
    return 0;
}

}  // namespace luxel::cli
