// luxel.render for 2D scenes and media: the solver, its options, the backend, bounce light and
// progress, in the order `luxel render` runs them (apps/cli/commands/render.cpp).
#include "solvers.h"

#include <memory>

#include "arrays.h"
#include "gpu.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/voxel/voxel_scene.h"
#include "medium.h"
#include "progress.h"

namespace luxel::python {
namespace {

using gi2d::Medium2D;
using gi2d::Solver2D;

struct SolverChoice {
    Solver2D solver = Solver2D::Reference;
    gi2d::RcMerge merge = gi2d::RcMerge::BilinearFix;
};

// "rc-vanilla" is RC with the vanilla merge; `merge` picks the RC merge by name otherwise.
SolverChoice parseSolverArgs(const Solve2DArgs& args) {
    SolverChoice choice;
    std::string name = args.solver.value_or("reference");
    if (name == "rc-vanilla") {
        if (args.merge) throw LuxelError("solver='rc-vanilla' picks the merge; leave out merge");
        name = "rc";
        choice.merge = gi2d::RcMerge::Vanilla;
    }
    choice.solver = unwrap(gi2d::parseSolver2D(name, "solver"));
    if (args.merge) {
        if (choice.solver != Solver2D::Rc) throw LuxelError("merge applies to solver='rc'");
        choice.merge = unwrap(gi2d::parseRcMerge(*args.merge, "merge"));
    }
    return choice;
}

// The options of the solvers the choice does not run are refused, as the CLI would ignore them
// silently otherwise.
void refuseOthers(const Solve2DArgs& args, Solver2D solver) {
    const bool reference = solver == Solver2D::Reference, hrc = solver == Solver2D::Hrc;
    const bool rc = solver == Solver2D::Rc;
    const char* name = gi2d::solverName(solver);
    auto refuse = [&](bool given, bool applies, const char* option, const char* owner) {
        if (given && !applies) {
            throw LuxelError(std::string(option) + " applies to solver='" + owner + "', not '" +
                             name + "'");
        }
    };
    refuse(args.rays.has_value(), reference, "rays", "reference");
    refuse(args.seed.has_value(), reference, "seed", "reference");
    refuse(args.tracedLevels.has_value(), hrc, "traced_levels", "hrc");
    refuse(args.crossBlur.has_value(), hrc, "cross_blur", "hrc");
    refuse(args.nearField.has_value(), hrc, "near_field", "hrc");
    refuse(args.directLight.has_value(), hrc, "direct_light", "hrc");
    refuse(args.probeSpacing.has_value(), rc, "probe_spacing", "rc");
    refuse(args.baseRays.has_value(), rc, "base_rays", "rc");
    refuse(args.baseInterval.has_value(), rc, "base_interval", "rc");
    refuse(args.maxCascades.has_value(), rc, "max_cascades", "rc");
    refuse(args.jitters.has_value(), rc, "jitters", "rc");
}

// One solve of `lit` (the medium, or it with bounce light added), reporting to `relay`.
Result<Image> solveOnce(const Medium2D& lit, const SolverChoice& choice, const Solve2DArgs& args,
                        gpu::Context* context, ProgressRelay& relay) {
    switch (choice.solver) {
        case Solver2D::Reference: {
            gi2d::ReferenceOptions options;
            options.rays = args.rays.value_or(options.rays);
            options.seed = args.seed.value_or(options.seed);
            options.onRowsDone = [&](int rows) { relay.advance(static_cast<std::uint64_t>(rows)); };
            return gi2d::solveReference(lit, options);
        }
        case Solver2D::Hrc: {
            gi2d::HrcOptions options;
            options.tracedLevels = args.tracedLevels.value_or(options.tracedLevels);
            options.crossBlur = args.crossBlur.value_or(options.crossBlur);
            options.exactNearField = args.nearField.value_or(options.exactNearField);
            options.exactDirectLight = args.directLight.value_or(options.exactDirectLight);
            options.onProgress = [&](int, int) { relay.advance(); };
            return context ? gi2d::solveHrcOnGpu(*context, lit, options)
                           : gi2d::solveHrc(lit, options);
        }
        case Solver2D::Rc: {
            gi2d::RcOptions options;
            options.merge = choice.merge;
            options.probeSpacing = args.probeSpacing.value_or(options.probeSpacing);
            options.baseRays = args.baseRays.value_or(options.baseRays);
            options.baseInterval = args.baseInterval.value_or(options.baseInterval);
            options.maxCascades = args.maxCascades.value_or(options.maxCascades);
            options.jitters = args.jitters.value_or(options.jitters);
            auto fluence =
                context ? gi2d::solveRcOnGpu(*context, lit, options) : gi2d::solveRc(lit, options);
            relay.advance();  // RC reports no progress of its own: one step per solve
            return fluence;
        }
    }
    return Error("unknown solver");
}

// Progress units per solve: rows for the reference, frustums for HRC, one solve for RC.
std::uint64_t progressUnits(Solver2D solver, const Medium2D& medium) {
    switch (solver) {
        case Solver2D::Reference:
            return static_cast<std::uint64_t>(medium.height());
        case Solver2D::Hrc:
            return 4;
        case Solver2D::Rc:
            return 1;
    }
    return 1;
}

py::array_t<float> renderMedium(const Medium2D& medium, const Solve2DArgs& args,
                                const RenderCommon& common) {
    check(validateMedium(medium));
    const SolverChoice choice = parseSolverArgs(args);
    refuseOthers(args, choice.solver);
    checkThreads(common.threads);
    const gpu::Backend backend = parseBackendArg(common.backend);
    if (choice.solver == Solver2D::Reference && backend == gpu::Backend::Gpu) {
        throw LuxelError("backend='gpu': the reference solver runs on the CPU only");
    }
    const int maxBounces = gi2d::kMaxReferenceBounces;
    if (args.bounces && (*args.bounces < 0 || *args.bounces > maxBounces)) {
        throw LuxelError("bounces must be in 0.." + std::to_string(maxBounces) + ", got " +
                         std::to_string(*args.bounces));
    }
    // Bounce light as the CLI runs it: the reference converges unless `bounces` caps it, HRC and
    // RC feed the fluence back kDefaultCascadeBounces times (gi2d/bounce.h).
    const bool reference = choice.solver == Solver2D::Reference;
    const bool bouncing = medium.bounces() && args.bounces.value_or(-1) != 0;
    gi2d::BounceOptions bounce;
    bounce.maxBounces = args.bounces.value_or(reference ? gi2d::kMaxReferenceBounces
                                                        : gi2d::kDefaultCascadeBounces);
    if (reference && !args.bounces) bounce.tolerance = gi2d::kReferenceTolerance;

    std::unique_ptr<gpu::Context> context =
        reference ? nullptr : openBackendFor(backend, common.device);
    ProgressRelay relay(common.progress, progressUnits(choice.solver, medium),
                        bouncing ? bounce.maxBounces + 1 : 1);
    Result<Image> fluence = Error("");
    {
        py::gil_scoped_release release;
        ThreadLimit limit(common.threads);
        fluence = runCancellable([&]() -> Result<Image> {
            if (!bouncing) return solveOnce(medium, choice, args, context.get(), relay);
            int part = 0;
            auto result = gi2d::solveWithBounces(
                medium,
                [&](const Medium2D& lit) {
                    relay.beginPart(part++);
                    return solveOnce(lit, choice, args, context.get(), relay);
                },
                bounce);
            if (!result) return result.error();
            return std::move(result->fluence);
        });
    }
    relay.rethrowIfFailed();
    py::array_t<float> out = imageToArray(unwrap(std::move(fluence)));
    relay.finish();
    return out;
}

py::object render(py::handle source, const Solve2DArgs& args, const RenderCommon& common) {
    if (py::isinstance<voxel::VoxelScene>(source)) {
        if (const std::string given = args.firstGiven(); !given.empty()) {
            throw LuxelError(given + " applies to 2D scenes; this is a voxel scene");
        }
        return renderVoxelScene(source, common);
    }
    if (py::isinstance<Medium2D>(source)) {
        if (args.width || args.height || args.supersample) {
            throw LuxelError(
                "width, height and supersample apply when rendering a Scene2D; a "
                "Medium has its size already");
        }
        return renderMedium(source.cast<const Medium2D&>(), args, common);
    }
    if (py::isinstance<gi2d::Scene2D>(source)) {
        const auto medium = rasterizeScene(source.cast<const gi2d::Scene2D&>(), args.width,
                                           args.height, args.supersample.value_or(16));
        return renderMedium(*medium, args, common);
    }
    throw py::type_error("render: expected a Scene2D, Medium or VoxelScene, got " +
                         py::str(py::type::of(source)).cast<std::string>());
}

}  // namespace

std::string Solve2DArgs::firstGiven() const {
    const std::pair<bool, const char*> options[] = {
        {solver.has_value(), "solver"},
        {width.has_value() || height.has_value(), "width/height"},
        {supersample.has_value(), "supersample"},
        {rays.has_value(), "rays"},
        {seed.has_value(), "seed"},
        {bounces.has_value(), "bounces"},
        {tracedLevels.has_value(), "traced_levels"},
        {crossBlur.has_value(), "cross_blur"},
        {nearField.has_value(), "near_field"},
        {directLight.has_value(), "direct_light"},
        {merge.has_value(), "merge"},
        {probeSpacing.has_value(), "probe_spacing"},
        {baseRays.has_value(), "base_rays"},
        {maxCascades.has_value(), "max_cascades"},
        {jitters.has_value(), "jitters"},
        {baseInterval.has_value(), "base_interval"}};
    for (const auto& [given, name] : options) {
        if (given) return name;
    }
    return "";
}

void checkThreads(int threads) {
    if (threads < 0 || threads > 4096) {
        throw LuxelError("threads must be in 0..4096 (0: all cores), got " +
                         std::to_string(threads));
    }
}

void bindSolvers(py::module_& m) {
    m.def(
        "render",
        [](py::handle source, std::optional<std::string> solver, std::optional<int> width,
           std::optional<int> height, std::optional<int> supersample, std::optional<int> rays,
           std::optional<std::uint64_t> seed, std::optional<int> bounces,
           std::optional<int> tracedLevels, std::optional<bool> crossBlur,
           std::optional<bool> nearField, std::optional<std::string> merge,
           std::optional<int> probeSpacing, std::optional<int> baseRays,
           std::optional<double> baseInterval, std::optional<int> maxCascades,
           std::optional<int> jitters, std::optional<bool> directLight, std::string backend,
           std::string device, int threads, py::object progress) {
            const Solve2DArgs args{solver,       width,        height,       supersample, rays,
                                   seed,         bounces,      tracedLevels, crossBlur,   nearField,
                                   merge,        probeSpacing, baseRays,     maxCascades, jitters,
                                   baseInterval, directLight};
            const RenderCommon common{std::move(backend), std::move(device), threads,
                                      std::move(progress)};
            return render(source, args, common);
        },
        py::arg("source"), py::arg("solver") = py::none(), py::kw_only(),
        py::arg("width") = py::none(), py::arg("height") = py::none(),
        py::arg("supersample") = py::none(), py::arg("rays") = py::none(),
        py::arg("seed") = py::none(), py::arg("bounces") = py::none(),
        py::arg("traced_levels") = py::none(), py::arg("cross_blur") = py::none(),
        py::arg("near_field") = py::none(), py::arg("merge") = py::none(),
        py::arg("probe_spacing") = py::none(), py::arg("base_rays") = py::none(),
        py::arg("base_interval") = py::none(), py::arg("max_cascades") = py::none(),
        py::arg("jitters") = py::none(), py::arg("direct_light") = py::none(),
        py::arg("backend") = "auto", py::arg("device") = "", py::arg("threads") = 0,
        py::arg("progress") = py::none(),
        R"(Renders a Scene2D or Medium to its fluence, a float32 array (height, width, 3) that owns
the image (no copy). A VoxelScene goes to render_voxel.

solver: "reference" (default; rays, seed), "hrc" (traced_levels, cross_blur, near_field: the
exact gather next to lights where fog bounds the rays, on by default; direct_light: the compact
lights' direct light added exactly, on by default), "rc" (merge
"bilinear-fix" or "vanilla", probe_spacing, base_rays, base_interval, max_cascades, jitters) or
"rc-vanilla". width/height/supersample rasterise a Scene2D at another size. bounces: times the
fluence is fed back in scenes with albedo (default: the reference converges, hrc and rc bounce
16 times; 0 = off). backend: "auto" (a hardware GPU when there is one), "cpu" or "gpu" (hrc
and rc; "gpu" raises luxel.Error when no Vulkan device can be opened). threads: 0 = all cores.
progress: called with the fraction done (increasing, ends at 1.0); an exception it raises, or
Ctrl-C, cancels the solve and propagates. The GIL is released while solving.)");
}

}  // namespace luxel::python
