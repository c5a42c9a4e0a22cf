// luxel-view: interactive viewer for 2D scenes (radiance cascades), voxel worlds and sparse voxel
// octrees.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app.h"
#include "common/last_resort.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/scene2d_json.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"
#include "luxel/post/frame_memory.h"
#include "luxel/scene/scene_file.h"
#include "luxel/voxel/voxel_scene.h"
#include "mode_2d.h"
#include "mode_octree.h"
#include "mode_voxel.h"
#include "script_events.h"
#include "viewer_options.h"

namespace {

using namespace luxel;
using namespace luxel::viewer;

int fail(const std::string& message) {
    std::fprintf(stderr, "luxel-view: error: %s\n", message.c_str());
    return kExitBadInput;
}

// Scales (w, h) down to fit in maxW x maxH, keeping the aspect ratio.
std::pair<int, int> fitWithin(int w, int h, int maxW, int maxH) {
    const double s = std::min({1.0, static_cast<double>(maxW) / w, static_cast<double>(maxH) / h});
    return {std::max(1, static_cast<int>(std::lround(w * s))),
            std::max(1, static_cast<int>(std::lround(h * s)))};
}

// Internal resolution: --internal-size, else --internal-scale x base, else the default.
std::pair<int, int> internalSize(const ViewerOptions& o, int baseW, int baseH,
                                 std::pair<int, int> fallback) {
    if (o.internalWidth > 0) return {o.internalWidth, o.internalHeight};
    if (o.internalScale > 0) {
        return {std::max(1, static_cast<int>(std::lround(baseW * o.internalScale))),
                std::max(1, static_cast<int>(std::lround(baseH * o.internalScale)))};
    }
    return fallback;
}

// Whether Vulkan lists a GPU that is not a software device (what --backend auto would use).
bool hasHardwareGpu() {
    auto devices = gpu::listDevices();
    if (!devices) return false;
    for (const gpu::DeviceInfo& d : *devices) {
        if (gpu::autoUsesDevice(d)) return true;
    }
    return false;
}

// The frames the viewer keeps on the host: the internal render and its post-processing at the
// window size (luxel/post/frame_memory.h), a GPU frame's download, and the window's RGBA texture
// and screenshot. Refused in one line before any is allocated.
Status checkFrameMemory(std::pair<int, int> internal, int windowW, int windowH) {
    const ImageSize frame{internal.first, internal.second}, window{windowW, windowH};
    const std::uint64_t internalPixels =
        static_cast<std::uint64_t>(frame.width) * static_cast<std::uint64_t>(frame.height);
    const std::uint64_t windowPixels =
        static_cast<std::uint64_t>(window.width) * static_cast<std::uint64_t>(window.height);
    const std::uint64_t needed = post::finishedFrameBytes(frame, window, post::PostOptions{}) +
                                 post::kGpuDownloadBytesPerPixel * internalPixels +
                                 windowPixels * 4 * 2;
    return checkMemory(
        needed, "viewing at " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                    " in a " + std::to_string(windowW) + "x" + std::to_string(windowH) + " window");
}

std::string defaultSavePath(const std::string& scenePath) {
    return std::filesystem::path(scenePath).stem().string() + ".painted.json";
}

int runViewer(int argc, char** argv) {
    auto parsed = parseViewerOptions(std::vector<std::string>(argv + 1, argv + argc));
    if (!parsed) return fail(parsed.error().message());
    if (parsed->helpRequested) {
        std::printf("%s", parsed->helpText.c_str());
        return 0;
    }
    const ViewerOptions& o = parsed->options;
    ThreadLimit threadLimit(o.threads);

    std::optional<Script> script;
    if (!o.script.empty()) {
        auto loaded = loadScript(o.script, isKnownKeyName);
        if (!loaded) return fail(loaded.error().message());
        script = std::move(*loaded);
    }

    std::unique_ptr<ViewerMode> mode;
    int windowW = o.windowWidth, windowH = o.windowHeight;
    // The backend policy of the CLI (luxel/gpu/backend_policy.h): --backend gpu needs a device.
    if (o.backend == gpu::Backend::Gpu) {
        auto opened = gpu::openBackend(gpu::Backend::Gpu, {o.device, false});
        if (!opened) return fail(opened.error().message());
    }
    auto file = scene::loadSceneFile(o.scene, {{}, o.voxFrame});
    if (!file) return fail(file.error().message());
    if (file->kind() != scene::SceneKind::Voxel) {
        if (o.voxelSolver && *o.voxelSolver != VoxelSolver::Cascades) {
            return fail(std::string("--solver ") + voxelSolverName(*o.voxelSolver) +
                        " applies to voxel scenes");
        }
        if (!o.voxelFlagsGiven.empty()) {
            return fail(o.voxelFlagsGiven.front() + " applies to voxel scenes");
        }
    }
    if (file->kind() == scene::SceneKind::Voxel) {
        voxel::VoxelScene* scene = &file->voxel();
        if (o.solver2DGiven && o.voxelSolver != VoxelSolver::Cascades) {
            return fail(std::string("--solver ") + gi2d::solverName(o.solver) +
                        " is a 2D solver; voxel scenes take raycast, ao, path or rc");
        }
        VoxelSolverOptions solver;
        solver.kind = o.voxelSolver.value_or(VoxelSolver::RayCast);
        solver.path = o.path;
        solver.ao = o.ao;
        if (windowW == 0) {
            std::tie(windowW, windowH) =
                fitWithin(scene->camera.width(), scene->camera.height(), 1280, 720);
        }
        std::unique_ptr<VoxelFrameSource> source;
        if (o.backend != gpu::Backend::Cpu) {
            // auto takes hardware GPUs only, like the CLI; gpu also accepts lavapipe.
            auto gpuSource = makeGpuVoxelFrameSource(o.device, o.backend == gpu::Backend::Auto,
                                                     scene->world, scene->textures);
            if (gpuSource) {
                source = std::move(*gpuSource);
            } else if (o.backend == gpu::Backend::Gpu) {
                std::fprintf(stderr, "luxel-view: note: using the CPU backend (%s)\n",
                             gpuSource.error().message().c_str());
            }
        }
        // A hardware GPU renders the full window. On the CPU (and on a software device such as
        // lavapipe, which is slower) a quarter of the window side keeps the ray caster near 10
        // frames per second on two cores (240x135 for the 960x540 terrain view).
        if (!source) source = makeCpuVoxelFrameSource(scene->textures);
        const std::pair<int, int> fallback =
            source->hardwareGpu() ? std::pair{windowW, windowH}
                                  : std::pair{std::max(1, windowW / 4), std::max(1, windowH / 4)};
        const auto internal = internalSize(o, windowW, windowH, fallback);
        if (Status s = checkFrameMemory(internal, windowW, windowH); !s) {
            return fail(s.error().message());
        }
        for (const std::string& w : scene->warnings) {
            std::fprintf(stderr, "luxel-view: warning: %s\n", w.c_str());
        }
        mode = std::make_unique<ModeVoxel>(
            std::move(*scene), internal.first, internal.second, o.exposure, std::move(source),
            o.savePath.empty() ? defaultVoxSavePath(o.scene) : o.savePath, solver);
    } else if (file->kind() == scene::SceneKind::Octree) {
        scene::OctreeScene* scene = &file->octree();
        if (windowW == 0) {
            std::tie(windowW, windowH) =
                fitWithin(scene->camera.width(), scene->camera.height(), 1280, 720);
        }
        std::unique_ptr<OctreeFrameSource> source;
        if (o.backend != gpu::Backend::Cpu) {
            auto gpuSource =
                makeGpuOctreeFrameSource(o.device, o.backend == gpu::Backend::Auto, scene->tree);
            if (gpuSource) {
                source = std::move(*gpuSource);
            } else if (o.backend == gpu::Backend::Gpu) {
                std::fprintf(stderr, "luxel-view: note: using the CPU backend (%s)\n",
                             gpuSource.error().message().c_str());
            }
        }
        // As voxel mode: a hardware GPU renders the full window; the CPU (and lavapipe) a
        // quarter of the side, about 20 ms a surface frame of the shipped world (240x135) on two
        // cores. Volume scattering is far slower; slow frames are previewed at a quarter of that.
        if (!source) source = makeCpuOctreeFrameSource();
        const std::pair<int, int> fallback =
            source->hardwareGpu() ? std::pair{windowW, windowH}
                                  : std::pair{std::max(1, windowW / 4), std::max(1, windowH / 4)};
        const auto internal = internalSize(o, windowW, windowH, fallback);
        if (Status s = checkFrameMemory(internal, windowW, windowH); !s) {
            return fail(s.error().message());
        }
        mode = std::make_unique<ModeOctree>(std::move(*scene), internal.first, internal.second,
                                            o.exposure, std::move(source));
    } else {
        gi2d::Scene2D* scene = &file->twoD();
        if (windowW == 0)
            std::tie(windowW, windowH) = fitWithin(scene->width, scene->height, 1280, 900);
        // With a hardware GPU the canvas (up to 512 px) renders interactively; HRC on a 2-core
        // CPU manages about 20 frames per second at 128 px on the long side.
        const int side = o.backend != gpu::Backend::Cpu && hasHardwareGpu() ? 512 : 128;
        const auto internal = internalSize(o, scene->width, scene->height,
                                           fitWithin(scene->width, scene->height, side, side));
        if (Status s = checkFrameMemory(internal, windowW, windowH); !s) {
            return fail(s.error().message());
        }
        Mode2DSettings settings;
        settings.view.solver = o.solver;
        settings.view.merge = o.merge;
        settings.view.backend = o.backend;
        settings.view.device = o.device;
        settings.view.exposure = o.exposure;
        settings.view.width = internal.first;
        settings.view.height = internal.second;
        settings.savePath = o.savePath.empty() ? defaultSavePath(o.scene) : o.savePath;
        mode = std::make_unique<Mode2D>(std::move(*scene), settings);
    }
    return runApp(o, *mode, std::move(script), windowW, windowH);
}

}  // namespace

int main(int argc, char** argv) {
    return luxel::options::runUntilOutOfMemory("luxel-view", "viewing the scene",
                                               [&] { return runViewer(argc, argv); });
}
