// `luxel compare-solvers`: every 2D solver on one scene (voxel scenes: compare_solvers_voxel.cpp),
// each in its own process so its peak memory can be measured: solve time, error against the
// reference solver, peak RSS; optionally a side-by-side image grid of the display images and one of
// each solver's signed error (docs/solver-errors.md). With --move, how each solver's image changes
// when the light moves. On voxel scenes, --sun-sweep N renders every solver under N sun directions
// and measures its flicker (compare_sun_sweep.cpp).
// --reference reuses a reference render instead of solving it again.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/compare_moving_light.h"
#include "commands/compare_solvers_run.h"
#include "commands/error_image.h"
#include "commands/render_outputs.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/metrics.h"
#include "luxel/gi2d/display.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/post/label.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/voxel_scene.h"

extern char** environ;

namespace luxel::cli {
namespace {

struct CompareSolversArgs {
    std::string scene, size, grid, errorImage, move, reference;
    int rays = 1024;
    bool raysGiven = false;
    int spp = 256;             // voxel scenes: the path-traced reference's samples per pixel
    int samples = 0;           // voxel scenes: the pictures' samples per pixel (0: the scene's)
    int adaptiveSamples = -1;  // voxel scenes: the cascades' adaptive samples (-1: the scene's)
    double errorScalePercent = 10;
    int sunSweep = 0;    // voxel scenes: frames of the sun sweep (0: none)
    double sunStep = 1;  // degrees between them
    bool sunStepGiven = false;
};

// A sweep renders every solver N times: without --size it renders small, kSweepWidth pixels wide
// (or the camera's width, if less) at the camera's aspect.
constexpr int kSweepWidth = 128;
constexpr int kMaxSunSweep = 360;

// --reference: a fluence EXR that `luxel render --solver reference` wrote for this scene at this
// size, checked by its size and, where its metadata has them, its solver and scene hash.
Result<RunOutcome> reuseReference(const CompareSolversArgs& args, int& rays) {
    if (!hasExtension(args.reference, ".exr")) {
        return Error("--reference '" + args.reference +
                     "' must be a fluence EXR (luxel render --solver reference --out FILE.exr)");
    }
    ImageMetadata metadata;
    auto fluence = readExr(args.reference, &metadata);
    if (!fluence) return fluence.error();
    auto sized = loadSizedScene(args.scene, args.size);
    if (!sized) return sized.error();
    if (fluence->width() != sized->width || fluence->height() != sized->height) {
        return Error("--reference '" + args.reference + "' is " + std::to_string(fluence->width()) +
                     "x" + std::to_string(fluence->height()) + " but " + args.scene +
                     " renders at " + std::to_string(sized->width) + "x" +
                     std::to_string(sized->height) + (args.size.empty() ? "" : " (--size)"));
    }
    if (const std::string* solver = findMetadata(metadata, "luxel.solver");
        solver != nullptr && *solver != "reference") {
        return Error("--reference '" + args.reference + "' was rendered by the " + *solver +
                     " solver, not the reference");
    }
    if (const std::string* hash = findMetadata(metadata, "luxel.scene.fnv1a64")) {
        auto bytes = readFileBytes(args.scene, "scene");
        if (!bytes) return bytes.error();
        if (*hash != fnv1a64Hex(*bytes)) {
            return Error("--reference '" + args.reference +
                         "' was rendered from another version of " + args.scene +
                         " (scene FNV-1a " + *hash + ", the file's now " + fnv1a64Hex(*bytes) +
                         ")");
        }
    }
    if (const std::string* given = findMetadata(metadata, "luxel.rays")) rays = std::stoi(*given);
    auto medium = rasterizeSized(*sized, args.scene, 16);
    if (!medium) return medium.error();
    RunOutcome out;
    if (const std::string* seconds = findMetadata(metadata, "luxel.render.seconds")) {
        out.solveMs = std::stod(*seconds) * 1e3;
    }
    out.display = gi2d::displayImage(*medium, *fluence, ToneMapSettings{});
    out.fluence = std::move(*fluence);
    return out;
}

}  // namespace

std::string formatDuration(double ms) {
    char text[32];
    if (ms < 10000) {
        std::snprintf(text, sizeof text, "%.0f ms", ms);
    } else {
        std::snprintf(text, sizeof text, "%.1f s", ms / 1000);
    }
    return text;
}

Status writeLabelledGrid(const std::string& path, std::vector<Image> panels,
                         const std::vector<std::string>& labels, const ImageMetadata& metadata) {
    const int scale = post::panelLabelScale(labels, panels.front().width());
    for (std::size_t i = 0; i < panels.size(); ++i) {
        post::drawPanelLabel(panels[i], 0, panels[i].width(), labels[i], scale);
    }
    return writePng(path, sideBySide(panels), PngEncoding::Srgb, metadata);
}

Result<RunOutcome> runSolverProcess(const std::string& scene, const std::string& size,
                                    const SolverRun& solver, const std::filesystem::path& dir) {
    const std::string exr = (dir / (std::string(solver.label) + ".exr")).string();
    const std::string png = (dir / (std::string(solver.label) + ".png")).string();
    const std::string log = (dir / (std::string(solver.label) + ".log")).string();
    std::vector<std::string> argv = {"/proc/self/exe", "render", scene,   "--quiet", "--stats",
                                     "--out",          exr,      "--png", png};
    if (!size.empty()) argv.insert(argv.end(), {"--size", size});
    argv.insert(argv.end(), solver.flags.begin(), solver.flags.end());
    std::vector<char*> cargv;
    for (std::string& a : argv) cargv.push_back(a.data());
    cargv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    pid_t pid = 0;
    const int spawned =
        posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, cargv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return Error(std::string("cannot start a solver process: ") + std::strerror(spawned));
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) < 0) return Error("lost the solver process");

    std::string output;
    if (FILE* f = std::fopen(log.c_str(), "r")) {
        char line[512];
        while (std::fgets(line, sizeof line, f)) output += line;
        std::fclose(f);
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        return Error(std::string(solver.label) + " failed: " + output);
    }
    RunOutcome out;
    const auto at = output.find("stats solve_seconds=");
    if (at != std::string::npos) out.solveMs = std::stod(output.substr(at + 20)) * 1e3;
    out.peakBytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // KiB on Linux
    auto fluence = readExr(exr);
    if (!fluence) return fluence.error();
    out.fluence = std::move(*fluence);
    auto display = readPng(png);
    if (!display) return display.error();
    out.display = std::move(*display);
    return out;
}

Result<std::vector<RunOutcome>> runSolverProcesses(const std::string& scene,
                                                   const std::string& size,
                                                   std::span<const SolverRun> solvers) {
    std::error_code ec;
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("luxel-compare-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir, ec);
    if (ec) return Error("cannot create " + dir.string() + ": " + ec.message());
    std::vector<RunOutcome> runs;
    for (const SolverRun& solver : solvers) {
        auto run = runSolverProcess(scene, size, solver, dir);
        if (!run) {
            std::filesystem::remove_all(dir, ec);
            return run.error();
        }
        runs.push_back(std::move(*run));
    }
    std::filesystem::remove_all(dir, ec);
    return runs;
}

namespace {

int runCompareSolvers(const CompareSolversArgs& args) {
    if (access(args.scene.c_str(), R_OK) != 0) {
        return reportError(Error("cannot open scene '" + args.scene + "'"));
    }
    if (auto size = parseSize(args.size); !size) return reportError(size.error());
    auto file = loadScene(args.scene, "");
    if (!file) return reportError(file.error());
    if (file->kind() == scene::SceneKind::Voxel) {
        for (const auto& [flag, given] : {std::pair{"--move", !args.move.empty()},
                                          {"--error-image", !args.errorImage.empty()},
                                          {"--rays", args.raysGiven}}) {
            if (given) {
                return reportError(Error(std::string(flag) + " applies to 2D scenes; " +
                                         args.scene +
                                         " is a voxel scene (--spp sets the path "
                                         "tracer's samples)"));
            }
        }
        if (args.sunStepGiven && args.sunSweep == 0) {
            return reportError(Error("--sun-step applies to --sun-sweep"));
        }
        if (!args.reference.empty() && (args.sunSweep > 0 || !args.grid.empty())) {
            return reportError(Error(std::string("--reference does not apply to ") +
                                     (args.sunSweep > 0 ? "--sun-sweep" : "--grid") +
                                     " on a voxel scene (it renders the reference itself)"));
        }
        std::string size = args.size;
        if (args.sunSweep > 0 && size.empty()) {
            const voxel::Camera& camera = file->voxel().camera;
            const int w = std::min(kSweepWidth, camera.width());
            const int h = std::max(
                1, static_cast<int>(std::lround(double(w) * camera.height() / camera.width())));
            size = std::to_string(w) + "x" + std::to_string(h);
        }
        return compareVoxelSolvers({args.scene, size, args.grid, args.spp, args.sunSweep,
                                    args.sunStep, args.reference, args.samples,
                                    args.adaptiveSamples});
    }
    if (args.samples > 0 || args.adaptiveSamples >= 0) {
        return reportError(
            Error(std::string(args.samples > 0 ? "--samples" : "--adaptive-samples") +
                  " applies to voxel scenes; " + args.scene + " is " +
                  sceneKindPhrase(file->kind()) + " (--rays sets the reference)"));
    }
    if (args.sunSweep > 0 || args.sunStepGiven) {
        return reportError(Error(std::string(args.sunSweep > 0 ? "--sun-sweep" : "--sun-step") +
                                 " applies to voxel scenes; " + args.scene + " is " +
                                 sceneKindPhrase(file->kind())));
    }
    if (file->kind() != scene::SceneKind::TwoD) {
        return reportError(Error(args.scene + ": " + sceneKindPhrase(file->kind()) +
                                 "; compare-solvers compares the 2D and the voxel solvers"));
    }
    if (!args.move.empty() && !args.reference.empty()) {
        return reportError(
            Error("--reference does not apply to --move, which renders both lights"));
    }
    if (!args.move.empty()) {
        return runCompareMovingLight(
            {args.scene, args.size, args.move, args.errorImage, args.rays, args.errorScalePercent});
    }
    int referenceRays = args.rays;
    std::optional<RunOutcome> reused;
    if (!args.reference.empty()) {
        auto outcome = reuseReference(args, referenceRays);
        if (!outcome) return reportError(outcome.error());
        reused = std::move(*outcome);
    }
    // The CPU paths, so peak memory is the solver's own (no Vulkan driver loaded); RC marches the
    // pixel medium as the reference does.
    std::vector<SolverRun> solvers = {
        {"reference", {"--solver", "reference", "--rays", std::to_string(referenceRays)}},
        {"hrc", {"--solver", "hrc", "--backend", "cpu"}},
        {"rc-vanilla",
         {"--solver", "rc", "--merge", "vanilla", "--march", "dda", "--backend", "cpu"}},
        {"rc-bilinear-fix",
         {"--solver", "rc", "--merge", "bilinear-fix", "--march", "dda", "--backend", "cpu"}},
    };
    // A second reference with other random directions: its difference from the first shows the
    // reference's own noise (sqrt(2) times one image's).
    if (!args.errorImage.empty()) {
        solvers.push_back(
            {"reference-seed2",
             {"--solver", "reference", "--rays", std::to_string(referenceRays), "--seed", "2"}});
    }
    // A reused reference stands in for the first run.
    auto solved = runSolverProcesses(args.scene, args.size,
                                     std::span<const SolverRun>(solvers).subspan(reused ? 1 : 0));
    if (!solved) return reportError(solved.error());
    std::vector<RunOutcome> runs;
    if (reused) runs.push_back(std::move(*reused));
    for (RunOutcome& run : *solved) runs.push_back(std::move(run));

    const Image& reference = runs[0].fluence;
    std::printf("%s at %dx%d (reference: %d rays/pixel%s%s)\n", args.scene.c_str(),
                reference.width(), reference.height(), referenceRays,
                args.reference.empty() ? "" : ", from ", args.reference.c_str());
    std::printf("%-16s %10s %10s %10s %9s %12s\n", "solver", "ms", "rel. L1", "RMSE", "RMSE/mean",
                "peak memory");
    for (std::size_t i = 0; i < runs.size(); ++i) {
        auto e = compareImages(runs[i].fluence, reference);
        if (!e) return reportError(e.error());
        std::printf("%-16s %10.1f %10.4f %10.5f %8.2f%% %12s\n", solvers[i].label, runs[i].solveMs,
                    e->relativeL1, e->rmse,
                    e->meanReference > 0 ? 100.0 * e->rmse / e->meanReference : 0.0,
                    runs[i].peakBytes > 0 ? formatBytes(runs[i].peakBytes).c_str() : "-");
    }
    if (!args.grid.empty()) {
        // Each panel says what it is: the solver, its time and its error against the reference.
        const char* names[] = {"reference", "hrc", "rc vanilla", "rc bilinear fix"};
        std::vector<Image> displays;
        ImageMetadata metadata =
            renderMetadata(args.scene, "compare-solvers", reference.width(), reference.height());
        setNumber(metadata, "luxel.rays", referenceRays);
        std::vector<std::string> labels;
        for (std::size_t i = 0; i < 4; ++i) {
            std::string label = names[i];
            if (i == 0) {
                label += "\n" + std::to_string(referenceRays) + " rays" +
                         (runs[0].solveMs > 0 ? ", " + formatDuration(runs[0].solveMs) : "");
            } else {
                char error[64];
                std::snprintf(error, sizeof error, ", rel. L1 %.4f",
                              compareImages(runs[i].fluence, reference)->relativeL1);
                label += "\n" + formatDuration(runs[i].solveMs) + error;
            }
            labels.push_back(label);
            std::string key = names[i];
            for (char& c : key) c = c == ' ' ? '_' : c;
            setMetadata(metadata, "luxel.panel" + std::to_string(i + 1) + "." + key,
                        label.substr(label.find('\n') + 1));
        }
        for (std::size_t i = 0; i < 4; ++i) displays.push_back(runs[i].display);
        setMetadata(metadata, "luxel.content", "display, tonemapped; panels left to right");
        if (Status s = writeLabelledGrid(args.grid, std::move(displays), labels, metadata); !s) {
            return reportError(s.error());
        }
        std::printf("wrote %s (left to right: reference, hrc, rc vanilla, rc bilinear fix)\n",
                    args.grid.c_str());
    }
    if (!args.errorImage.empty()) {
        const double mean = compareImages(reference, reference)->meanReference;
        const double scale = args.errorScalePercent / 100.0;
        std::vector<Image> panels = {runs[0].display};
        for (std::size_t i : {std::size_t{4}, std::size_t{1}, std::size_t{2}, std::size_t{3}}) {
            panels.push_back(divergingColours(
                signedRelativeDifference(runs[i].fluence, reference, mean), scale));
        }
        ImageMetadata metadata =
            renderMetadata(args.scene, "compare-solvers", reference.width(), reference.height());
        setNumber(metadata, "luxel.rays", referenceRays);
        setNumber(metadata, "luxel.error_scale_percent", args.errorScalePercent);
        setMetadata(metadata, "luxel.content",
                    "reference display, then the signed error of reference seed 2, hrc, rc "
                    "vanilla, rc bilinear fix");
        if (Status s = writePng(args.errorImage, sideBySide(panels), PngEncoding::Srgb, metadata);
            !s) {
            return reportError(s.error());
        }
        std::printf(
            "wrote %s (left to right: reference, then the signed error of reference seed 2, hrc, "
            "rc vanilla, rc bilinear fix; white 0, red +%g%%, blue -%g%% of the mean)\n",
            args.errorImage.c_str(), args.errorScalePercent, args.errorScalePercent);
    }
    return 0;
}

}  // namespace

Runner addCompareSolversCommand(CLI::App& app) {
    auto args = std::make_shared<CompareSolversArgs>();
    app.add_option("scene", args->scene, "scene file (.json)")->required();
    app.add_option("--size", args->size, "render size WIDTHxHEIGHT (default: the scene canvas)");
    app.add_option("--rays", args->rays, "reference directions per pixel")
        ->check(wholeIn(1, gi2d::kMaxReferenceRays))
        ->capture_default_str();
    app.add_option("--spp", args->spp,
                   "voxel scenes: samples per pixel of the path-traced reference")
        ->check(wholeIn(2, voxel::kMaxPathSamples))
        ->capture_default_str();
    app.add_option("--samples", args->samples,
                   "voxel scenes: samples per pixel of the other solvers' pictures, stratified "
                   "(default: the scene's render.samples)")
        ->check(wholeIn(1, voxel::kMaxSamplesPerPixel));
    app.add_option("--adaptive-samples", args->adaptiveSamples,
                   "voxel scenes: samples per pixel where the radiance cascades' picture has "
                   "strong contrast, 0 off (default: the scene's render.adaptive_samples)")
        ->check(wholeIn(0, voxel::kMaxSamplesPerPixel));
    app.add_option("--grid", args->grid, "write the display images side by side (.png)");
    app.add_option("--error-image", args->errorImage,
                   "write the reference and each solver's signed error side by side (.png)");
    app.add_option("--error-scale", args->errorScalePercent,
                   "error image: the error (% of the mean fluence) drawn fully red or blue")
        ->check(CLI::Range(0.001, 1000.0))
        ->capture_default_str();
    app.add_option("--reference", args->reference,
                   "reuse this reference fluence (.exr from luxel render --solver reference; "
                   "voxel scenes: --solver path) instead of solving it again; checked against "
                   "the scene's size and hash");
    app.add_option("--move", args->move,
                   "move the brightest light by DX,DY px and compare each solver's change");
    app.add_option("--sun-sweep", args->sunSweep,
                   "voxel scenes: render every solver at N sun directions (--sun-step apart) "
                   "and measure its flicker (default size 128 px wide)")
        ->check(wholeIn(2, kMaxSunSweep));
    app.add_option("--sun-step", args->sunStep,
                   "voxel scenes, --sun-sweep: degrees the sun turns about the vertical per frame")
        ->check(finiteIn(-90, 90))
        ->capture_default_str();
    CLI::App* command = &app;
    return [args, command] {
        args->raysGiven = command->count("--rays") > 0;
        args->sunStepGiven = command->count("--sun-step") > 0;
        if (args->sunStepGiven && args->sunStep == 0) {
            return reportError(Error("--sun-step must not be 0 (the sun would not move)"));
        }
        return runCompareSolvers(*args);
    };
}

}  // namespace luxel::cli
