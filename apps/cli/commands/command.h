// The CLI's subcommands. Each registers its options on the app and runs when selected; run
// functions return the process exit code.
#pragma once

#include <CLI/CLI.hpp>

#include "common/number_options.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/tonemap.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/scene2d.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/fwd.h"
#include "luxel/post/post_options.h"
#include "luxel/scene/scene_file.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/sky_visibility.h"

namespace luxel::cli {

using Runner = std::function<int()>;

Runner addRenderCommand(CLI::App& app);
Runner addInfoCommand(CLI::App& app);
Runner addCompareCommand(CLI::App& app);
Runner addRasterCommand(CLI::App& app);
Runner addCompareSolversCommand(CLI::App& app);
Runner addDevicesCommand(CLI::App& app);
Runner addBenchCommand(CLI::App& app);
Runner addOctreeCommand(CLI::App& app);
Runner addShadowsCommand(CLI::App& app);
Runner addConvertCommand(CLI::App& app);

// "a voxel scene", "an octree scene", "a 2D scene": for messages that refuse a scene's kind.
const char* sceneKindPhrase(scene::SceneKind kind);

// Prints "luxel: error: <message>" to stderr and returns the exit code for bad input.
int reportError(const Error& error);

// Whether `path` ends in `ext` (lower-case, with the dot), ignoring case.
bool hasExtension(const std::string& path, const std::string& ext);

// Numeric option checks (common/number_options.h). A failed check is a CLI::ValidationError,
// which main prints as one "luxel: error:" line naming the option.
using options::finiteIn;
using options::wholeIn;

// "512x384" -> (512, 384); an empty string gives (0, 0) = the scene's own size.
Result<std::pair<int, int>> parseSize(const std::string& text);

// A scene file and the size it will be rendered at.
struct SizedScene {
    gi2d::Scene2D scene;
    int width = 0, height = 0;
};

// Reads a scene file once, whatever its type (luxel/scene/scene_file.h); `size` ("" or WxH)
// overrides a voxel scene's camera size, `voxFrame` >= 0 the animation frame of a MagicaVoxel
// world. A voxel scene's warnings are printed ("luxel: warning: m.vox: ...").
Result<scene::SceneFile> loadScene(const std::string& scenePath, const std::string& size,
                                   int voxFrame = -1);
// Prints each as "luxel: warning: <text>" to stderr.
void printWarnings(const std::vector<std::string>& warnings);
// `--frame N`: the animation frame of a MagicaVoxel world (-1 when not given).
void addVoxFrameOption(CLI::App& app, int& frame);

// A 2D scene at the size it will be rendered at: `size` overrides its canvas ("" = its own).
Result<SizedScene> sizeScene(gi2d::Scene2D scene, const std::string& size);

// Loads a 2D scene (a voxel scene is an error naming the file) at a size, as sizeScene.
Result<SizedScene> loadSizedScene(const std::string& scenePath, const std::string& size);

// Rasterises a loaded scene at its render size.
Result<gi2d::Medium2D> rasterizeSized(const SizedScene& sized, const std::string& scenePath,
                                      int supersample);

// Both of the above.
Result<gi2d::Medium2D> loadMedium(const std::string& scenePath, const std::string& size,
                                  int supersample);

inline constexpr int kExitBadInput = 1;

// The GPU for `--backend` on `--device` (luxel/gpu/backend_policy.h): nullptr means the CPU path.
// gpu fails when no device can be opened; auto skips software devices (lavapipe is slower than
// the CPU path) and, unless quiet, notes on stderr why it uses the CPU. Debug builds turn on the
// validation layers.
Result<std::unique_ptr<gpu::Context>> chooseGpuBackend(gpu::Backend backend,
                                                       const std::string& device, bool quiet);

// `luxel bench --backend`: cpu or gpu (a benchmark names what it measures, so no auto).
Result<gpu::Backend> parseBenchBackend(const std::string& text);

// The GPU for `luxel bench --backend gpu` (no validation layers, which would skew timings), with
// its name printed; fails with "--backend gpu: <reason>".
Result<std::unique_ptr<gpu::Context>> openBenchGpu(const std::string& device);

// `luxel render` flags that override a scene's "post" section (unset: the scene's value).
struct PostFlags {
    std::optional<float> bloom, internalScale, sharpness, exposure;
    std::optional<ToneCurve> tone;
    std::optional<post::Upscaler> upscaler;
};
post::PostOptions applyPostFlags(post::PostOptions scene, const PostFlags& flags);
// `luxel render` flags overriding a voxel scene's surface lighting (empty: the scene's).
struct VoxelSurfaceFlags {
    std::string lighting, specular, fresnel;
    bool noRefraction = false;
    std::string shadows;          // --shadows: render.shadows' method (empty: the scene's)
    bool noEmitterLight = false;  // --no-emitter-light: render.emitter_light false
    int emitterRays = 0;          // --emitter-rays: render.emitter_rays (0: the scene's)
    int skyAmbientRays = -1;      // --sky-ambient-rays: render.sky_ambient_rays (-1: the scene's)
};
void addVoxelSurfaceFlags(CLI::App& app, VoxelSurfaceFlags& flags);
// Applies them to the scene's shading options; errors name the flag.
Status applyVoxelSurfaceFlags(const VoxelSurfaceFlags& flags, voxel::ShadeOptions& options);

// A voxel scene render (`luxel render` on a file with "type": "voxel").
struct VoxelRenderRequest {
    std::string scene, size, out, png;
    ToneMapSettings tone;
    bool quiet = false, stats = false;
    gpu::Backend backend = gpu::Backend::Auto;
    std::string device;      // --device
    double loadSeconds = 0;  // reading the scene (generators included)
    PostFlags post;          // --bloom, --internal-scale, --upscaler, --sharpness, tone flags
    VoxelSurfaceFlags surfaces;
    // --samples and --filter (0, empty: the scene's).
    int samples = 0;
    std::string filter = {};
    int adaptiveSamples = -1;   // --adaptive-samples (-1: the scene's), --solver rc
    bool autoExposure = false;  // --exposure auto (commands/render_outputs.h)
    // --solver path: the path tracer (voxel/path_trace.h) instead of the ray caster.
    bool pathSolver = false;
    voxel::PathTraceOptions path = {};
    std::string pathStdError = {};  // --std-error: where the standard error image goes (.exr)
    // --solver ao: sky visibility (voxel/sky_visibility.h) instead of the ray caster.
    bool aoSolver = false;
    voxel::SkyVisibilityOptions ao = {};
    // --solver rc: radiance cascades (voxel/radiance_cascades.h) instead of the ray caster.
    bool cascadeSolver = false;
    voxel::CascadeOptions cascades = {};
    double sunYawDegrees = 0;  // --sun-yaw: the scene's sun turned about the vertical axis
};
int renderVoxelScene(const VoxelRenderRequest& request, voxel::VoxelScene scene);

// `luxel bench` on a voxel scene: frame times at each of `sizes` (comma-separated WxH; empty = the
// scene's camera size) on the CPU or the GPU.
struct VoxelBenchRequest {
    std::string scene;
    gpu::Backend backend = gpu::Backend::Cpu;  // cpu or gpu
    std::string device, sizes;
    int repeat = 3;
};
int benchVoxelScene(const VoxelBenchRequest& request, voxel::VoxelScene scene);

// Renders one frame at `camera`; on the GPU `timings` (else null) receives its dispatches.
using BenchFrame =
    std::function<Status(const voxel::Camera& camera, std::vector<gpu::PassTiming>* timings)>;
// The table `luxel bench` prints for voxel and octree scenes. benchSizes checks --repeat and
// --sizes first (the scene camera's size without --sizes); benchFrames prints the best of
// request.repeat frames at each size, after one warm-up frame on the GPU, whose dispatch time
// (transfers excluded) is printed next to the wall time.
Result<std::vector<ImageSize>> benchSizes(const VoxelBenchRequest& request,
                                          const voxel::Camera& camera);
int benchFrames(const VoxelBenchRequest& request, const std::vector<ImageSize>& sizes,
                const voxel::Camera& camera, bool onGpu, const BenchFrame& frame);

// `luxel info` on a voxel scene (`size`: WxH overriding the camera's image size, or empty).
int infoVoxelScene(const voxel::VoxelScene& scene);

// The same three for octree scenes ("type": "octree"); render takes the voxel request's fields.
int renderOctreeScene(const VoxelRenderRequest& request, scene::OctreeScene scene);
int benchOctreeScene(const VoxelBenchRequest& request, scene::OctreeScene scene);

// `luxel upscale`: native vs internal-resolution renders with each upscaler (PSNR, SSIM, ms).
Runner addUpscaleCommand(CLI::App& app);
int infoOctreeScene(const scene::OctreeScene& scene);

}  // namespace luxel::cli
