// `luxel render`: scene -> fluence image (EXR linear or PNG tonemapped) and display PNG.
#include <cstdio>
#include <memory>
#include <vector>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/core/progress.h"
#include "luxel/core/timer.h"
#include "luxel/core/tonemap.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/display.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/sdf_scene.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

struct RenderArgs {
    std::string scene, solverName = "reference", size, out, png, tonemap = "aces";
    gi2d::Solver2D solver = gi2d::Solver2D::Reference;  // parsed from solverName
    std::vector<std::string> options2DGiven;            // 2D-only options on the command line
    int rays = gi2d::ReferenceOptions{}.rays;
    int threads = 0;
    int supersample = 16;
    std::uint64_t seed = 1;
    float exposure = 0.0f;
    bool quiet = false;
    bool stats = false;  // print a machine-readable timing line (for compare-solvers)
    int frame = -1;      // --frame: a MagicaVoxel world's animation frame
    std::string backendName = "auto", device;
    gpu::Backend backend = gpu::Backend::Auto;  // parsed from backendName
    // HRC
    int tracedLevels = gi2d::HrcOptions{}.tracedLevels;
    bool noBlur = false;
    std::string frustum;  // debug: one of +x, +y, -x, -y
    int cascade = 0;      // debug: the cascade --view cascade|probes shows (hrc, rc)
    // RC
    std::string mergeName = "bilinear-fix", march = "auto", view = "gi";
    gi2d::RcMerge merge = gi2d::RcMerge::BilinearFix;  // parsed from mergeName
    int probeSpacing = gi2d::RcOptions{}.probeSpacing;
    int baseRays = gi2d::RcOptions{}.baseRays;
    double baseInterval = gi2d::RcOptions{}.baseInterval;
    int maxCascades = 0;
    int jitters = 1;
    // Bounce light: -1 = the solver's default when the scene bounces (gi2d/bounce.h)
    int bounces = -1;
    // Voxel and octree post-processing (override the scene's "post")
    float bloom = 0.0f, internalScale = 1.0f, sharpness = 0.0f;
    std::string upscalerName;
    PostFlags post;                      // the post flags given, parsed
    std::vector<std::string> postGiven;  // their names
    VoxelSurfaceFlags surfaces;          // voxel scenes
    // Voxel scenes: anti-aliasing and texture filtering (0 / empty: the scene's).
    int samples = 0;
    std::string filter;
};

// The names given on the command line -> the library's enums (luxel/gi2d/solver_choice.h,
// luxel/gpu/backend_policy.h), so the CLI and the viewer accept the same words.
Status parseChoices(RenderArgs& args) {
    auto solver = gi2d::parseSolver2D(args.solverName);
    if (!solver) return solver.error();
    auto merge = gi2d::parseRcMerge(args.mergeName);
    if (!merge) return merge.error();
    auto backend = gpu::parseBackend(args.backendName);
    if (!backend) return backend.error();
    args.solver = *solver;
    args.merge = *merge;
    args.backend = *backend;
    return Ok{};
}

// The post flags given on the command line; the rest come from the scene's "post" section.
Status parsePostFlags(RenderArgs& args, const CLI::App& command) {
    PostFlags& f = args.post;
    for (const char* name : {"--bloom", "--internal-scale", "--upscaler", "--sharpness"}) {
        if (command.count(name) > 0) args.postGiven.push_back(name);
    }
    if (command.count("--bloom") > 0) f.bloom = args.bloom;
    if (command.count("--internal-scale") > 0) f.internalScale = args.internalScale;
    if (command.count("--sharpness") > 0) f.sharpness = args.sharpness;
    if (command.count("--upscaler") > 0) {
        f.upscaler = post::parseUpscaler(args.upscalerName);
        if (!f.upscaler) {
            return Error("--upscaler '" + args.upscalerName + "' is not bilinear or edge");
        }
    }
    if (command.count("--exposure") > 0) f.exposure = args.exposure;
    if (command.count("--tonemap") > 0) f.tone = parseToneCurve(args.tonemap);
    return Ok{};
}

// Frustum name -> HRC frustum mask bit.
Result<unsigned> frustumMask(const std::string& name) {
    if (name.empty()) return 0xFu;
    const char* names[4] = {"+x", "+y", "-x", "-y"};
    for (unsigned r = 0; r < 4; ++r) {
        if (name == names[r]) return 1u << r;
    }
    return Error("--frustum '" + name + "' is not one of +x, +y, -x, -y");
}

// ", 16 jittered probe grids" in the summary line when RC averages several.
std::string jitterNote(const gi2d::RcOptions& options) {
    return options.jitters > 1 ? ", " + std::to_string(options.jitters) + " jittered probe grids"
                               : "";
}

gi2d::RcOptions rcOptions(const RenderArgs& args) {
    gi2d::RcOptions options;
    options.merge = args.merge;
    options.probeSpacing = args.probeSpacing;
    options.baseRays = args.baseRays;
    options.baseInterval = args.baseInterval;
    options.maxCascades = args.maxCascades;
    options.jitters = args.jitters;
    options.debugCascade = args.view == "cascade" ? std::max(args.cascade, 0) : -1;
    return options;
}

// The GPU context for --backend gpu, or for auto when a hardware device exists and the solver
// can use it; nullptr means the CPU path. auto falls back with a one-line note.
Result<std::unique_ptr<gpu::Context>> chooseGpu(const RenderArgs& args, bool gpuCapable) {
    if (args.backend == gpu::Backend::Gpu && !gpuCapable) {
        return Error("--backend gpu: this view runs on the CPU only");
    }
    if (!gpuCapable) return std::unique_ptr<gpu::Context>();
    return chooseGpuBackend(args.backend, args.device, args.quiet);
}

// RC: the DDA through the pixel medium every solver shares (--march auto or dda), on the GPU when
// one is chosen; sphere tracing of the exact shapes only when asked for (--march sdf), which solves
// a different problem than the rasterised medium the reference and HRC see.
Result<Image> solveRcFor(const RenderArgs& args, const SizedScene& sized,
                         const gi2d::Medium2D& medium, gpu::Context* context, std::string& detail) {
    const gi2d::RcOptions options = rcOptions(args);
    const std::string merge = gi2d::mergeName(args.merge);
    if (args.march != "auto" && args.march != "dda" && args.march != "sdf") {
        return Error("--march '" + args.march + "' is not auto, dda or sdf");
    }
    if (args.backend == gpu::Backend::Gpu && args.march == "sdf") {
        return Error("--backend gpu traces RC intervals with the DDA; use --march dda or auto");
    }
    // Bounce light changes the medium's emission, which sphere tracing does not see.
    if (medium.bounces() && args.bounces != 0 && args.march == "sdf") {
        return Error("--march sdf cannot carry bounce light; use --march dda or --bounces 0");
    }
    if (args.march == "sdf") {
        auto sdf = gi2d::SdfScene::create(sized.scene, sized.width, sized.height);
        if (!sdf) return Error("--march sdf: " + sdf.error().message());
        detail = "merge " + merge +
                 ", march sdf (exact shapes, not the rasterised medium the other solvers use), cpu";
        return gi2d::solveRc(*sdf, sized.scene.boundaryRadiance, options);
    }
    if (context) {
        detail =
            "merge " + merge + jitterNote(options) + ", march dda, gpu: " + context->device().name;
        return gi2d::solveRcOnGpu(*context, medium, options);
    }
    detail = "merge " + merge + jitterNote(options) + ", march dda, cpu";
    return gi2d::solveRc(medium, options);
}

Result<Image> solveReferenceFor(const RenderArgs& args, const gi2d::Medium2D& medium,
                                double& rays) {
    if (args.backend == gpu::Backend::Gpu) {
        return Error("--backend gpu: the reference solver is CPU-only");
    }
    const int w = medium.width(), h = medium.height();
    ProgressBar progress("reference", static_cast<std::uint64_t>(h), !args.quiet);
    gi2d::ReferenceOptions options;
    options.rays = args.rays;
    options.seed = args.seed;
    options.onRowsDone = [&](int n) { progress.advance(static_cast<std::uint64_t>(n)); };
    rays = static_cast<double>(gi2d::referenceRayCount(w, h, args.rays));
    return gi2d::solveReference(medium, options);
}

Result<Image> solveHrcFor(const RenderArgs& args, const gi2d::Medium2D& medium,
                          gpu::Context* context, std::string& detail) {
    auto mask = frustumMask(args.frustum);
    if (!mask) return mask.error();
    ProgressBar progress("hrc", 4, !args.quiet);
    gi2d::HrcOptions options;
    options.tracedLevels = args.tracedLevels;
    options.crossBlur = !args.noBlur;
    options.frustumMask = *mask;
    options.debugCascade = args.view == "cascade" ? std::max(args.cascade, 0) : -1;
    options.onProgress = [&](int, int) { progress.advance(); };
    if (context) {
        detail = "gpu: " + context->device().name;
        std::vector<gpu::PassTiming> timings;
        auto result = gi2d::solveHrcOnGpu(*context, medium, options, &timings);
        double total = 0;
        for (const gpu::PassTiming& t : timings) total += t.milliseconds;
        detail += ", passes " + std::to_string(timings.size()) + ", " +
                  std::to_string(static_cast<int>(total + 0.5)) + " ms summed";
        return result;
    }
    detail = "cpu";
    return gi2d::solveHrc(medium, options);
}

// The GPU context the chosen solver runs on (nullptr: the CPU), chosen once per render so bounce
// light does not probe the devices again for every solve. The reference and RC's sphere tracing
// run on the CPU and report --backend gpu themselves; so does an RC with an unknown --march.
Result<std::unique_ptr<gpu::Context>> chooseSolverGpu(const RenderArgs& args) {
    switch (args.solver) {
        case gi2d::Solver2D::Reference:
            return std::unique_ptr<gpu::Context>();
        case gi2d::Solver2D::Hrc:
            // A bad --frustum is reported before any device is probed.
            if (auto mask = frustumMask(args.frustum); !mask) return mask.error();
            return chooseGpu(args, args.view != "cascade");
        case gi2d::Solver2D::Rc:
            if (args.march != "auto" && args.march != "dda") return std::unique_ptr<gpu::Context>();
            return chooseGpu(args, true);
    }
    return Error("unknown solver");
}

// Runs the chosen solver with a progress bar; sets `rays` to the number of rays cast (0 when the
// solver does not cast rays per pixel) and `detail` to how it ran.
Result<Image> solve(const RenderArgs& args, const SizedScene& sized, const gi2d::Medium2D& medium,
                    gpu::Context* context, double& rays, std::string& detail) {
    rays = 0;
    switch (args.solver) {
        case gi2d::Solver2D::Reference:
            return solveReferenceFor(args, medium, rays);
        case gi2d::Solver2D::Hrc:
            return solveHrcFor(args, medium, context, detail);
        case gi2d::Solver2D::Rc:
            return solveRcFor(args, sized, medium, context, detail);
    }
    return Error("unknown solver");
}

// The chosen solver with bounce light fed back (gi2d/bounce.h) when the medium bounces: the
// reference converges unless --bounces caps it, HRC and RC run --bounces (default
// kDefaultCascadeBounces) extra solves. `note` says what happened, for the summary line.
Result<Image> solveBouncing(const RenderArgs& args, const SizedScene& sized,
                            const gi2d::Medium2D& medium, double& rays, std::string& detail,
                            std::string& note) {
    if (medium.bounces() && args.view == "cascade") {
        return Error("--view cascade shows one solve; use --bounces 0");
    }
    auto context = chooseSolverGpu(args);
    if (!context) return context.error();
    if (!medium.bounces()) {
        note = "no bounce light";
        return solve(args, sized, medium, context->get(), rays, detail);
    }
    const bool reference = args.solver == gi2d::Solver2D::Reference;
    gi2d::BounceOptions options;
    options.maxBounces =
        args.bounces >= 0 ? args.bounces
                          : (reference ? gi2d::kMaxReferenceBounces : gi2d::kDefaultCascadeBounces);
    if (reference && args.bounces < 0) options.tolerance = gi2d::kReferenceTolerance;
    double totalRays = 0;
    auto result = gi2d::solveWithBounces(
        medium,
        [&](const gi2d::Medium2D& lit) {
            double r = 0;
            auto f = solve(args, sized, lit, context->get(), r, detail);
            totalRays += r;
            return f;
        },
        options);
    if (!result) return result.error();
    rays = totalRays;
    char text[128];
    std::snprintf(
        text, sizeof text, "%d bounces%s (last change %.2g%s)", result->bounces,
        options.tolerance > 0 ? (result->converged ? ", converged" : ", NOT converged") : "",
        result->change, options.tolerance > 0 ? "" : ", fixed count");
    note = text;
    return std::move(result->fluence);
}

// Marks the probe centres of cascade --cascade (RC layout) on the display image.
void drawProbes(const RenderArgs& args, Image& display) {
    const auto cascades = gi2d::rcCascades(display.width(), display.height(), rcOptions(args));
    const int c = std::clamp(args.cascade, 0, static_cast<int>(cascades.size()) - 1);
    const gi2d::RcCascade& cascade = cascades[c];
    for (int py = 0; py < cascade.probesY; ++py) {
        for (int px = 0; px < cascade.probesX; ++px) {
            const int x = static_cast<int>((px + 0.5) * cascade.spacing);
            const int y = static_cast<int>((py + 0.5) * cascade.spacing);
            if (display.inside(x, y)) display.setRgb(x, y, Rgb(1.0f, 0.2f, 0.1f));
        }
    }
}

int runRender(const RenderArgs& args) {
    if (!hasExtension(args.out, ".exr") && !hasExtension(args.out, ".png")) {
        return reportError(Error("--out '" + args.out + "' must end in .exr or .png"));
    }
    auto curve = parseToneCurve(args.tonemap);
    if (!curve) {
        return reportError(
            Error("--tonemap '" + args.tonemap + "' is unknown (clamp, reinhard, aces)"));
    }
    const ToneMapSettings tone{args.exposure, *curve};
    ThreadLimit threadLimit(args.threads);
    Stopwatch loadTime;
    auto file = loadScene(args.scene, args.size, args.frame);
    if (!file) return reportError(file.error());
    if (file->kind() == scene::SceneKind::TwoD && !args.postGiven.empty()) {
        return reportError(Error(args.postGiven.front() + " applies to voxel and octree scenes; " +
                                 args.scene + " is " + sceneKindPhrase(file->kind())));
    }
    if (file->kind() != scene::SceneKind::TwoD) {
        const bool voxel = file->kind() == scene::SceneKind::Voxel;
        if (!args.options2DGiven.empty()) {
            return reportError(Error(args.options2DGiven.front() + " applies to 2D scenes; " +
                                     args.scene + " is " + sceneKindPhrase(file->kind())));
        }
        VoxelRenderRequest request{args.scene,  args.size,          args.out,   args.png,
                                   tone,        args.quiet,         args.stats, args.backend,
                                   args.device, loadTime.seconds(), args.post,  args.surfaces};
        request.samples = args.samples;
        request.filter = args.filter;
        if (!voxel && (args.samples != 0 || !args.filter.empty())) {
            return reportError(Error("--samples and --filter apply to voxel scenes; " + args.scene +
                                     " is " + sceneKindPhrase(file->kind())));
        }
        return voxel ? renderVoxelScene(request, std::move(file->voxel()))
                     : renderOctreeScene(request, std::move(file->octree()));
    }

    auto sized = sizeScene(std::move(file->twoD()), args.size);
    if (!sized) return reportError(sized.error());
    // Refuse before allocating anything when the medium, the solver and the images written
    // cannot fit (`luxel info` reports the same estimate).
    Memory2D memory = estimate2D(sized->width, sized->height, args.solver, rcOptions(args),
                                 args.bounces != 0 && gi2d::sceneBounces(sized->scene));
    if (args.view == "nogi") memory.solver = 0;
    if (Status s = checkRenderMemory(sized->width, sized->height, memory.total(),
                                     std::string(" with ") + gi2d::solverName(args.solver));
        !s) {
        return reportError(s.error());
    }
    Stopwatch rasterTime;
    auto medium = rasterizeSized(*sized, args.scene, args.supersample);
    if (!medium) return reportError(medium.error());
    const double rasterSeconds = rasterTime.seconds();
    const int w = medium->width(), h = medium->height();

    if (args.view != "gi" && args.view != "nogi" && args.view != "probes" &&
        args.view != "cascade") {
        return reportError(Error("--view '" + args.view + "' is not gi, nogi, probes or cascade"));
    }
    Stopwatch solveTime;
    double rays = 0;
    std::string detail;
    std::string bounceNote;
    Result<Image> fluence = args.view == "nogi"
                                ? Result<Image>(Image(w, h, 3))
                                : solveBouncing(args, *sized, *medium, rays, detail, bounceNote);
    if (!fluence) return reportError(fluence.error());
    const double solveSeconds = solveTime.seconds();

    const Image out = hasExtension(args.out, ".png") ? toneMap(*fluence, tone) : *fluence;
    // --out and --png change together or not at all (writeImages renames only once both are
    // complete).
    std::vector<ImageFile> files{{args.out, &out}};
    Image display;
    if (!args.png.empty()) {
        if (!hasExtension(args.png, ".png")) {
            return reportError(Error("--png '" + args.png + "' must end in .png"));
        }
        display = gi2d::displayImage(*medium, *fluence, tone);
        if (args.view == "probes") {
            drawProbes(args, display);
        }
        files.push_back({args.png, &display});
    }
    if (Status s = writeImages(files); !s) return reportError(s.error());
    if (args.stats) std::printf("stats solve_seconds=%.6f\n", solveSeconds);
    if (!args.quiet) {
        std::printf("%s: %dx%d, solver %s%s%s%s, %s, %d threads\n", args.scene.c_str(), w, h,
                    gi2d::solverName(args.solver), detail.empty() ? "" : " (", detail.c_str(),
                    detail.empty() ? "" : ")", bounceNote.c_str(),
                    args.threads > 0 ? args.threads : hardwareThreads());
        std::printf("  raster %.3f s, solve %.3f s (%.2f Mpixel/s", rasterSeconds, solveSeconds,
                    static_cast<double>(w) * h / solveSeconds * 1e-6);
        if (rays > 0) {
            std::printf(", %.2f Mrays/s at %d rays/pixel", rays / solveSeconds * 1e-6, args.rays);
        }
        std::printf(")\n  wrote %s%s%s\n", args.out.c_str(), args.png.empty() ? "" : ", ",
                    args.png.c_str());
    }
    return 0;
}

}  // namespace

Runner addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    app.add_option("scene", args->scene, "scene file (.json)")->required();
    app.add_option("--solver", args->solverName, "light transport solver: reference, hrc, rc")
        ->capture_default_str();
    app.add_option("--size", args->size, "render size WIDTHxHEIGHT (default: the scene canvas)");
    addVoxFrameOption(app, args->frame);
    app.add_option("--rays", args->rays, "directions per pixel (reference solver)")
        ->check(wholeIn(1, gi2d::kMaxReferenceRays))
        ->capture_default_str();
    app.add_option("--threads", args->threads, "worker threads (0 = all cores)")
        ->check(wholeIn(0, 4096))
        ->capture_default_str();
    app.add_option("--seed", args->seed, "random seed (reference solver)")->capture_default_str();
    app.add_option("--supersample", args->supersample, "edge samples per pixel side")
        ->check(wholeIn(1, 64))
        ->capture_default_str();
    app.add_option("--traced-levels", args->tracedLevels,
                   "HRC: cascades traced exactly; the rest by ray extension (1 = extend from c0)")
        ->check(wholeIn(1, 64))
        ->capture_default_str();
    app.add_flag("--no-blur", args->noBlur, "HRC: skip the opacity-gated cross blur (Eq 21)");
    app.add_option("--frustum", args->frustum, "HRC debug: only this frustum (+x, +y, -x, -y)");
    app.add_option("--cascade", args->cascade,
                   "debug: the cascade that --view cascade|probes shows")
        ->check(wholeIn(0, 64))
        ->capture_default_str();
    app.add_option("--merge", args->mergeName, "RC: vanilla or bilinear-fix")
        ->capture_default_str();
    app.add_option("--march", args->march,
                   "RC: interval tracing: auto = dda (the pixel medium all solvers share), sdf "
                   "(exact shapes)")
        ->capture_default_str();
    app.add_option("--probe-spacing", args->probeSpacing, "RC: cascade-0 probe spacing (px)")
        ->check(wholeIn(1, 64))
        ->capture_default_str();
    app.add_option("--base-rays", args->baseRays, "RC: cascade-0 directions per probe")
        ->check(wholeIn(1, 1024))
        ->capture_default_str();
    app.add_option("--base-interval", args->baseInterval, "RC: cascade-0 interval length (px)")
        ->check(finiteIn(1e-3, 1e5))
        ->capture_default_str();
    app.add_option("--jitters", args->jitters,
                   "RC: solves averaged, each with the probe grids above cascade 0 shifted "
                   "differently (fewer blotches, less popping as lights move; N times the time)")
        ->check(wholeIn(1, 256))
        ->capture_default_str();
    app.add_option("--max-cascades", args->maxCascades, "RC: cap on the cascade count (0 = none)")
        ->check(wholeIn(0, 16))
        ->capture_default_str();
    app.add_option("--bounces", args->bounces,
                   "bounce light (scenes with albedo): fluence fed back this many times; 0 = off "
                   "(default: the reference converges, hrc and rc bounce " +
                       std::to_string(gi2d::kDefaultCascadeBounces) + " times)")
        ->check(wholeIn(0, gi2d::kMaxReferenceBounces));
    app.add_option("--view", args->view,
                   "gi (default), nogi (emission only), probes (RC probe grid of --cascade on the "
                   "--png image), cascade (the merged radiance of --cascade)")
        ->capture_default_str();
    app.add_option("--out", args->out, "fluence image: .exr (linear float) or .png (tonemapped)")
        ->required();
    app.add_option("--png", args->png, "also write the display image (emission + fluence)");
    app.add_option("--exposure", args->exposure, "exposure in stops for PNG output")
        ->check(finiteIn(-64.0, 64.0))
        ->capture_default_str();
    app.add_option("--tonemap", args->tonemap, "tone curve for PNG output: clamp, reinhard, aces")
        ->capture_default_str();
    app.add_flag("--quiet,-q", args->quiet, "no progress bar or summary");
    app.add_flag("--stats", args->stats, "print 'stats solve_seconds=S' (for scripts)");
    app.add_option("--backend", args->backendName,
                   "auto (a hardware GPU when there is one, else CPU), cpu or gpu (HRC, RC, voxel)")
        ->capture_default_str();
    app.add_option("--device", args->device, "GPU: device index or part of its name");
    app.add_option("--bloom", args->bloom, "voxel/octree: bloom strength in [0, 1] (0 = off)")
        ->check(finiteIn(0.0, 1.0));
    app.add_option("--internal-scale", args->internalScale,
                   "voxel/octree: render at this fraction of the size, then upscale")
        ->check(finiteIn(double(post::kMinInternalScale), 1.0));
    app.add_option("--upscaler", args->upscalerName, "voxel/octree: bilinear or edge");
    app.add_option("--sharpness", args->sharpness, "voxel/octree: sharpening after upscaling")
        ->check(finiteIn(0.0, 1.0));
    addVoxelSurfaceFlags(app, args->surfaces);
    app.add_option("--samples", args->samples,
                   "voxel: samples per pixel, stratified (default: the scene's render.samples)")
        ->check(wholeIn(0, voxel::kMaxSamplesPerPixel));
    app.add_option(
        "--filter", args->filter,
        "voxel: texture filter nearest, trilinear or anisotropic (default: the scene's)");
    CLI::App* command = &app;
    return [args, command] {
        for (const char* name :
             {"--solver", "--rays", "--seed", "--supersample", "--traced-levels", "--no-blur",
              "--frustum", "--cascade", "--merge", "--march", "--probe-spacing", "--base-rays",
              "--base-interval", "--max-cascades", "--view", "--bounces"}) {
            if (command->count(name) > 0) args->options2DGiven.push_back(name);
        }
        if (Status s = parseChoices(*args); !s) return reportError(s.error());
        if (Status s = parsePostFlags(*args, *command); !s) return reportError(s.error());
        return runRender(*args);
    };
}

}  // namespace luxel::cli
