// luxel.render_voxel: a voxel scene, or a world and a camera, ray cast on the CPU or the GPU, then
// the scene's post-processing (internal resolution, upscaling, bloom), as `luxel render` does for
// voxel scenes (apps/cli/commands/render_voxel.cpp). The result is linear radiance.
#include <memory>
#include <optional>
#include <string>

#include "arrays.h"
#include "gpu.h"
#include "luxel/core/parallel.h"
#include "luxel/post/finish.h"
#include "luxel/post/upscale.h"
#include "luxel/post/voxel_frames.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_gpu.h"
#include "luxel/voxel/voxel_scene.h"
#include "progress.h"
#include "solvers.h"

namespace luxel::python {
namespace {

using voxel::Camera;
using voxel::VoxelScene;
using voxel::VoxelWorld;

// What one voxel render reads: a scene's parts, or a bare world with default shading.
struct VoxelJob {
    VoxelWorld* world = nullptr;
    Camera camera;
    voxel::ShadeOptions shading;
    const voxel::TextureSet* textures = nullptr;
    post::PostOptions post;
};

Result<Image> castImage(const VoxelJob& job, const Camera& camera, gpu::Context* context) {
    if (!context) return voxel::render(*job.world, camera, job.shading, job.textures);
    auto renderer = voxel::VoxelGpuRenderer::create(*context, *job.world, job.textures);
    if (!renderer) return renderer.error();
    return renderer->render(camera, job.shading);
}

// Shading settings a render may override (unset: the scene's, or the defaults for a world).
struct ShadingArgs {
    std::optional<int> samples, reflections;
    std::optional<bool> shadows;
    std::optional<std::string> lighting;
};

void applyShading(const ShadingArgs& args, voxel::ShadeOptions& shading) {
    using Options = voxel::ShadeOptions;
    if (args.samples) {
        if (*args.samples < 1 || *args.samples > voxel::kMaxSamplesPerPixel) {
            throw LuxelError("samples must be in 1.." + std::to_string(voxel::kMaxSamplesPerPixel) +
                             ", got " + std::to_string(*args.samples));
        }
        shading.samplesPerPixel = *args.samples;
    }
    if (args.reflections) {
        if (*args.reflections < 0 || *args.reflections > 16) {
            throw LuxelError("reflections must be in 0..16, got " +
                             std::to_string(*args.reflections));
        }
        shading.maxReflections = *args.reflections;
    }
    if (args.shadows) shading.shadows = *args.shadows;
    if (args.lighting) {
        if (*args.lighting == "classic") {
            shading.lighting = Options::Lighting::Classic;
        } else if (*args.lighting == "physical") {
            shading.lighting = Options::Lighting::Physical;
        } else {
            throw LuxelError("lighting '" + *args.lighting + "' is not classic or physical");
        }
    }
}

py::array_t<float> renderJob(VoxelJob& job, const ShadingArgs& shading, bool applyPost,
                             const RenderCommon& common) {
    checkThreads(common.threads);
    applyShading(shading, job.shading);
    // Edits through world[x, y, z] = ... leave the brick reach stale.
    if (!job.world->emptySpaceCurrent()) job.world->refreshEmptySpace();
    const std::unique_ptr<gpu::Context> context =
        openBackendFor(parseBackendArg(common.backend), common.device);
    const post::PostOptions post = applyPost ? job.post : post::PostOptions{};
    const int width = job.camera.width(), height = job.camera.height();
    const Camera camera =
        post.internalScale < 1.0f
            ? post::resizedCamera(job.camera, post::internalSide(width, post.internalScale),
                                  post::internalSide(height, post.internalScale))
            : job.camera;
    ProgressRelay relay(common.progress, 1);
    Result<Image> image = Error("");
    {
        py::gil_scoped_release release;
        ThreadLimit limit(common.threads);
        image = runCancellable([&]() -> Result<Image> {
            auto internal = castImage(job, camera, context.get());
            if (!internal) return internal.error();
            Image radiance = post::processInternal(*internal, width, height, post);
            relay.advance();  // the voxel renderer reports no progress of its own
            return radiance;
        });
    }
    relay.rethrowIfFailed();
    py::array_t<float> out = imageToArray(unwrap(std::move(image)));
    relay.finish();
    return out;
}

py::array_t<float> renderVoxel(py::handle source, std::optional<Camera> camera,
                               const ShadingArgs& shading, bool applyPost,
                               const RenderCommon& common) {
    VoxelJob job;
    if (py::isinstance<VoxelScene>(source)) {
        VoxelScene& scene = source.cast<VoxelScene&>();
        job = {&scene.world, camera.value_or(scene.camera), scene.shading, &scene.textures,
               scene.post};
    } else if (py::isinstance<VoxelWorld>(source)) {
        if (!camera) throw LuxelError("render_voxel: a VoxelWorld needs a camera");
        job.world = &source.cast<VoxelWorld&>();
        job.camera = *camera;
    } else {
        throw py::type_error("render_voxel: expected a VoxelScene or VoxelWorld, got " +
                             py::str(py::type::of(source)).cast<std::string>());
    }
    return renderJob(job, shading, applyPost, common);
}

}  // namespace

py::object renderVoxelScene(py::handle scene, const RenderCommon& common) {
    return renderVoxel(scene, std::nullopt, ShadingArgs{}, true, common);
}

void bindVoxelRender(py::module_& m) {
    m.def(
        "render_voxel",
        [](py::handle source, std::optional<Camera> camera, std::optional<int> samples,
           std::optional<int> reflections, std::optional<bool> shadows,
           std::optional<std::string> lighting, bool post, std::string backend, std::string device,
           int threads, py::object progress) {
            const RenderCommon common{std::move(backend), std::move(device), threads,
                                      std::move(progress)};
            const ShadingArgs shading{samples, reflections, shadows, std::move(lighting)};
            return renderVoxel(source, std::move(camera), shading, post, common);
        },
        py::arg("source"), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("samples") = py::none(), py::arg("reflections") = py::none(),
        py::arg("shadows") = py::none(), py::arg("lighting") = py::none(), py::arg("post") = true,
        py::arg("backend") = "auto", py::arg("device") = "", py::arg("threads") = 0,
        py::arg("progress") = py::none(),
        R"(Ray casts a VoxelScene (with its shading, textures and post-processing; `camera`
replaces the scene's) or a VoxelWorld with a Camera (default shading: sun, sky, hard shadows,
reflections). Returns linear radiance, float32 (height, width, 3), owning the image (no copy);
tonemap() it for display. samples: per pixel (1..256); reflections: mirror bounces (0..16);
shadows: sun shadows on or off; lighting: "classic" or "physical" (each unset: the scene's, or
the defaults for a world). post=False skips the scene's internal
resolution, upscaling and bloom. backend: "auto", "cpu" or "gpu" (raises luxel.Error when no
Vulkan device can be opened). progress: called with 1.0 when done (the voxel renderer reports
no steps). The GIL is released while rendering.)");
}

}  // namespace luxel::python
