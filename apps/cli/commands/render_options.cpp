// `luxel render`'s options: registration, and the names given -> the library's choices.
#include <memory>
#include <string_view>

#include "commands/render_args.h"
#include "luxel/gpu/backend_policy.h"

namespace luxel::cli {
namespace {

// The names given on the command line -> the library's enums (luxel/gi2d/solver_choice.h,
// luxel/gpu/backend_policy.h), so the CLI and the viewer accept the same words.
Status parseChoices(RenderArgs& args) {
    args.pathSolver = args.solverName == "path";
    args.aoSolver = args.solverName == "ao";
    args.rayCastSolver = args.solverName == "raycast";
    auto solver = args.pathSolver || args.aoSolver || args.rayCastSolver
                      ? Result<gi2d::Solver2D>(gi2d::Solver2D::Reference)
                      : gi2d::parseSolver2D(args.solverName);
    if (!solver) return Error(solver.error().message() + " (voxel scenes: raycast, path, ao, rc)");
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
    auto exposure = parseExposureFlag(args.exposureText);
    if (!exposure) return exposure.error();
    args.exposure = *exposure;
    f.exposure = exposure->stops;
    if (command.count("--tonemap") > 0) f.tone = parseToneCurve(args.tonemap);
    return Ok{};
}

}  // namespace

Runner addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    app.add_option("scene", args->scene, "scene file (.json)")->required();
    app.add_option(
           "--solver", args->solverName,
           "light transport solver: reference, hrc, rc (2D scenes); raycast (the default), path, "
           "ao, rc (voxel scenes)")
        ->capture_default_str();
    app.add_option("--size", args->size, "render size WIDTHxHEIGHT (default: the scene canvas)");
    addVoxFrameOption(app, args->frame);
    app.add_option("--rays", args->rays, "directions per pixel (reference solver)")
        ->check(wholeIn(1, gi2d::kMaxReferenceRays))
        ->capture_default_str();
    app.add_option("--threads", args->threads, "worker threads (0 = all cores)")
        ->check(wholeIn(0, 4096))
        ->capture_default_str();
    app.add_option("--seed", args->seed, "random seed (reference solver, path, ao)")
        ->capture_default_str();
    app.add_option("--supersample", args->supersample, "edge samples per pixel side")
        ->check(wholeIn(1, 64))
        ->capture_default_str();
    app.add_option("--traced-levels", args->tracedLevels,
                   "HRC: cascades traced exactly; the rest by ray extension (1 = extend from c0)")
        ->check(wholeIn(1, 64))
        ->capture_default_str();
    app.add_flag("--no-blur", args->noBlur, "HRC: skip the opacity-gated cross blur (Eq 21)");
    app.add_flag("--no-near-field", args->noNearField,
                 "HRC: skip the exact near field in fog (acts only where every pixel absorbs)");
    app.add_flag("--no-direct-light", args->noDirectLight,
                 "HRC: let the cascades carry the compact lights' direct light too");
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
    app.add_option("--out", args->out, "fluence image: .exr (linear float) or .png (tonemapped)");
    app.add_option("--png", args->png,
                   "the display image (emission + fluence, tonemapped); --out, --png or both");
    app.add_option("--exposure", args->exposureText,
                   "exposure in stops for PNG output, or auto (the 99th percentile of the lit "
                   "pixels at 90% of white); default 0, voxel scenes: the scene's");
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
    app.add_option("--adaptive-samples", args->adaptiveSamples,
                   "voxel, --solver rc: samples per pixel where the picture's contrast is strong, "
                   "0 off (default: the scene's render.adaptive_samples)")
        ->check(wholeIn(0, voxel::kMaxSamplesPerPixel));
    app.add_option(
        "--filter", args->filter,
        "voxel: texture filter nearest, trilinear or anisotropic (default: the scene's)");
    app.add_option("--spp", args->spp, "voxel, --solver path: samples per pixel")
        ->check(wholeIn(1, voxel::kMaxPathSamples))
        ->capture_default_str();
    app.add_option("--max-bounces", args->maxBounces,
                   "voxel, --solver path: most reflections of the light reaching the eye")
        ->check(wholeIn(0, voxel::kMaxPathBounces))
        ->capture_default_str();
    app.add_option("--std-error", args->stdError,
                   "voxel, --solver path: the standard error of each pixel's mean (.exr)");
    app.add_option("--ao-rays", args->aoRays,
                   "voxel, --solver ao: sky visibility rays per surface point")
        ->check(wholeIn(1, voxel::kMaxSkyRays))
        ->capture_default_str();
    app.add_option("--ao-radius", args->aoRadius,
                   "voxel, --solver ao: ray length in voxels (inf: whole sky visibility)")
        ->capture_default_str();
    app.add_option("--rc-spacing", args->rcSpacing,
                   "voxel, --solver rc: probe spacing of the first cascade level in voxels "
                   "(power of two; 0: automatic)")
        ->check(wholeIn(0, voxel::kMaxCascadeSpacing))
        ->capture_default_str();
    app.add_option("--sun-yaw", args->sunYaw,
                   "voxel: turn the scene's sun about the vertical axis by DEG degrees "
                   "(from +z towards +x)")
        ->check(finiteIn(-360, 360));
    CLI::App* command = &app;
    return [args, command] {
        args->rcSpacingGiven = command->count("--rc-spacing") > 0;
        args->sunYawGiven = command->count("--sun-yaw") > 0;
        for (const char* name : {"--spp", "--max-bounces", "--std-error"}) {
            if (command->count(name) > 0) args->pathGiven.push_back(name);
        }
        for (const char* name : {"--ao-rays", "--ao-radius"}) {
            if (command->count(name) > 0) args->aoGiven.push_back(name);
        }
        // --solver raycast/path/ao and --seed belong to voxel scenes (runRender refuses them for
        // 2D).
        const bool seeded = args->solverName == "path" || args->solverName == "ao";
        const bool voxelSolver = seeded || args->solverName == "raycast";
        for (const char* name :
             {"--solver", "--rays", "--seed", "--supersample", "--traced-levels", "--no-blur",
              "--no-near-field", "--no-direct-light", "--frustum", "--cascade", "--merge",
              "--march", "--probe-spacing", "--base-rays", "--base-interval", "--max-cascades",
              "--view", "--bounces"}) {
            // rc names a solver of both kinds; --bounces serves both (runRender sorts them out).
            const bool rcOption =
                args->solverName == "rc" &&
                (std::string_view(name) == "--solver" || std::string_view(name) == "--bounces");
            const bool voxelOption = (std::string_view(name) == "--solver" && voxelSolver) ||
                                     (std::string_view(name) == "--seed" && seeded);
            if (command->count(name) > 0 && !voxelOption && !rcOption) {
                args->options2DGiven.push_back(name);
            }
        }
        if (Status s = parseChoices(*args); !s) return reportError(s.error());
        if (Status s = parsePostFlags(*args, *command); !s) return reportError(s.error());
        return runRender(*args);
    };
}

}  // namespace luxel::cli
