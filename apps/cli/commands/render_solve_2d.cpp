// The 2D solve of `luxel render`: the chosen solver (reference, HRC or RC) on the GPU or the CPU,
// with bounce light fed back; render.cpp keeps the checks, the rasterising and the images.
#include "commands/render_solve_2d.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "luxel/core/progress.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/sdf_scene.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"

namespace luxel::cli {
namespace {

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
    options.exactNearField = !args.noNearField;
    options.exactDirectLight = !args.noDirectLight;
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

}  // namespace

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

}  // namespace luxel::cli
