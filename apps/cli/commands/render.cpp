// `luxel render`: scene -> fluence image (EXR linear or PNG tonemapped) and display PNG.
#include <algorithm>
#include <cstdio>
#include <vector>

#include "commands/command.h"
#include "commands/render_args.h"
#include "commands/render_memory.h"
#include "commands/render_outputs.h"
#include "commands/render_solve_2d.h"
#include "commands/scene_warnings.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "luxel/core/tonemap.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/display.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

// Marks the probe centres of cascade --cascade (RC layout) on canvas rows [y0, y1) of the display
// image (RGB floats, `width` pixels a row).
void drawProbes(const RenderArgs& args, int width, int height, float* rows, int y0, int y1) {
    const auto cascades = gi2d::rcCascades(width, height, rcOptions(args));
    const int c = std::clamp(args.cascade, 0, static_cast<int>(cascades.size()) - 1);
    const gi2d::RcCascade& cascade = cascades[c];
    for (int py = 0; py < cascade.probesY; ++py) {
        const int y = static_cast<int>((py + 0.5) * cascade.spacing);
        if (y < y0 || y >= y1) continue;
        for (int px = 0; px < cascade.probesX; ++px) {
            const int x = static_cast<int>((px + 0.5) * cascade.spacing);
            if (x < 0 || x >= width) continue;
            float* pixel = rows + (static_cast<std::size_t>(y - y0) * width + x) * 3;
            pixel[0] = 1.0f, pixel[1] = 0.2f, pixel[2] = 0.1f;
        }
    }
}

// The provenance of a 2D render: the solver and every setting it ran with (docs/image-metadata.md).
ImageMetadata metadata2D(const RenderArgs& args, int w, int h, const std::string& detail,
                         const std::string& bounceNote, double rasterSeconds, double solveSeconds) {
    ImageMetadata m = renderMetadata(args.scene, gi2d::solverName(args.solver), w, h);
    setMetadata(m, "luxel.view", args.view);
    setMetadata(m, "luxel.backend", detail.find("gpu") != std::string::npos ? "gpu" : "cpu");
    if (!detail.empty()) setMetadata(m, "luxel.solver.detail", detail);
    switch (args.solver) {
        case gi2d::Solver2D::Reference:
            setNumber(m, "luxel.rays", args.rays);
            setMetadata(m, "luxel.seed", std::to_string(args.seed));
            break;
        case gi2d::Solver2D::Hrc:
            setNumber(m, "luxel.hrc.cascades", gi2d::hrcCascadeCount(w, h));
            setNumber(m, "luxel.hrc.traced_levels", args.tracedLevels);
            setMetadata(m, "luxel.hrc.cross_blur", args.noBlur ? "no" : "yes");
            setMetadata(m, "luxel.hrc.near_field", args.noNearField ? "no" : "yes");
            setMetadata(m, "luxel.hrc.direct_light", args.noDirectLight ? "no" : "yes");
            if (!args.frustum.empty()) setMetadata(m, "luxel.hrc.frustum", args.frustum);
            break;
        case gi2d::Solver2D::Rc: {
            const gi2d::RcOptions options = rcOptions(args);
            setNumber(m, "luxel.rc.cascades",
                      static_cast<double>(gi2d::rcCascades(w, h, options).size()));
            setMetadata(m, "luxel.rc.merge", gi2d::mergeName(args.merge));
            setMetadata(m, "luxel.rc.march", args.march);
            setNumber(m, "luxel.rc.probe_spacing", args.probeSpacing);
            setNumber(m, "luxel.rc.base_rays", args.baseRays);
            setNumber(m, "luxel.rc.base_interval", args.baseInterval);
            setNumber(m, "luxel.rc.max_cascades", args.maxCascades);
            setNumber(m, "luxel.rc.jitters", args.jitters);
            break;
        }
    }
    if (!bounceNote.empty()) setMetadata(m, "luxel.bounces", bounceNote);
    setNumber(m, "luxel.supersample", args.supersample);
    setNumber(m, "luxel.threads", args.threads > 0 ? args.threads : hardwareThreads());
    setNumber(m, "luxel.raster.seconds", rasterSeconds);
    setNumber(m, "luxel.render.seconds", solveSeconds);
    return m;
}

}  // namespace

int runRender(const RenderArgs& args) {
    if (args.out.empty() && args.png.empty()) {
        return reportError(
            Error("nothing to write: give --out FILE.exr|FILE.png, --png FILE.png, "
                  "or both"));
    }
    if (!args.out.empty() && !hasExtension(args.out, ".exr") && !hasExtension(args.out, ".png")) {
        return reportError(Error("--out '" + args.out + "' must end in .exr or .png"));
    }
    if (!args.png.empty() && !hasExtension(args.png, ".png")) {
        return reportError(Error("--png '" + args.png + "' must end in .png"));
    }
    auto curve = parseToneCurve(args.tonemap);
    if (!curve) {
        return reportError(
            Error("--tonemap '" + args.tonemap + "' is unknown (clamp, reinhard, aces)"));
    }
    const ToneMapSettings tone{args.exposure.stops.value_or(0.0f), *curve};
    ThreadLimit threadLimit(args.threads);
    Stopwatch loadTime;
    if (!args.pathSolver && !args.pathGiven.empty()) {
        return reportError(Error(args.pathGiven.front() + " applies to --solver path"));
    }
    if (!args.aoSolver && !args.aoGiven.empty()) {
        return reportError(Error(args.aoGiven.front() + " applies to --solver ao"));
    }
    if (args.aoSolver && !(args.aoRadius > 0.0)) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", args.aoRadius);
        return reportError(
            Error("--ao-radius must be > 0 voxels (or inf), got " + std::string(text)));
    }
    auto file = loadScene(args.scene, args.size, args.frame);
    if (!file) return reportError(file.error());
    if ((args.pathSolver || args.aoSolver || args.rayCastSolver) &&
        file->kind() != scene::SceneKind::Voxel) {
        return reportError(Error("--solver " + args.solverName + " applies to voxel scenes; " +
                                 args.scene + " is " + sceneKindPhrase(file->kind())));
    }
    const bool voxelRc = args.solverName == "rc" && file->kind() == scene::SceneKind::Voxel;
    if (args.rcSpacingGiven && !voxelRc) {
        return reportError(Error("--rc-spacing applies to --solver rc on voxel scenes"));
    }
    if (args.solverName == "rc" && file->kind() == scene::SceneKind::Octree) {
        return reportError(Error("--solver rc applies to 2D and voxel scenes; " + args.scene +
                                 " is " + sceneKindPhrase(file->kind())));
    }
    if (file->kind() == scene::SceneKind::TwoD && args.frame >= 0) {
        return reportError(Error("--frame applies to MagicaVoxel worlds; " + args.scene + " is " +
                                 sceneKindPhrase(file->kind())));
    }
    if (args.sunYawGiven && file->kind() != scene::SceneKind::Voxel) {
        return reportError(Error("--sun-yaw applies to voxel scenes; " + args.scene + " is " +
                                 sceneKindPhrase(file->kind())));
    }
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
        request.adaptiveSamples = args.adaptiveSamples;
        request.filter = args.filter;
        request.autoExposure = args.exposure.automatic;
        request.pathSolver = args.pathSolver;
        request.path.samplesPerPixel = args.spp;
        request.path.maxBounces = args.maxBounces;
        request.path.seed = args.seed;
        request.pathStdError = args.stdError;
        request.aoSolver = args.aoSolver;
        request.ao = {args.aoRays, args.aoRadius, args.seed};
        request.cascadeSolver = voxelRc;
        request.cascades.spacing = args.rcSpacing;
        request.cascades.bounces = std::max(0, args.bounces);
        request.sunYawDegrees = args.sunYaw;
        if (!voxel && (args.samples != 0 || args.adaptiveSamples >= 0 || !args.filter.empty())) {
            return reportError(
                Error("--samples, --adaptive-samples and --filter apply to voxel "
                      "scenes; " +
                      args.scene + " is " + sceneKindPhrase(file->kind())));
        }
        return voxel ? renderVoxelScene(request, std::move(file->voxel()))
                     : renderOctreeScene(request, std::move(file->octree()));
    }

    auto sized = sizeScene(std::move(file->twoD()), args.size);
    if (!sized) return reportError(sized.error());
    if (!args.quiet) {
        for (const std::string& warning : silentEmitterWarnings(sized->scene)) {
            printWarning(args.scene + ": " + warning);
        }
    }
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

    // Only the light sources are read from here on (the display shows them with the light): the
    // rest of the medium goes before the images are written.
    medium->absorption = Image();
    medium->scattering = Image();
    medium->reflectance = Image();
    RenderImages images;
    images.out = args.out;
    images.png = args.png;
    images.linear = &*fluence;
    images.linearName = "fluence";
    // What the display image shows before tone mapping: the light sources and the light.
    images.displayHdr = &*fluence;
    images.displayAdd = &medium->emission;
    images.tone = tone;
    images.autoExposure = args.exposure.automatic;
    images.quiet = args.quiet;
    images.lightSources = &medium->emission;
    images.metadata = metadata2D(args, w, h, detail, bounceNote, rasterSeconds, solveSeconds);
    if (args.view == "probes") {
        images.drawOnDisplay = [&](float* rows, int, int y0, int y1) {
            drawProbes(args, w, h, rows, y0, y1);
        };
    }
    // --out and --png change together or not at all.
    if (Status s = writeRenderImages(std::move(images)); !s) return reportError(s.error());
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
        std::printf(")\n  wrote %s%s%s\n", args.out.c_str(),
                    args.out.empty() || args.png.empty() ? "" : ", ", args.png.c_str());
    }
    return 0;
}

}  // namespace luxel::cli
