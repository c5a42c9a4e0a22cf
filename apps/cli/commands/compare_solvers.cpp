// `luxel compare-solvers`: every 2D solver on one scene, each in its own process so its peak
// memory can be measured: solve time, error against the reference solver, peak RSS; optionally a
// side-by-side image grid of the display images and one of each solver's signed error
// (docs/solver-errors.md). With --move, how each solver's image changes when the light moves.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/compare_moving_light.h"
#include "commands/error_image.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/metrics.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/voxel/voxel_scene.h"

extern char** environ;

namespace luxel::cli {
namespace {

struct CompareSolversArgs {
    std::string scene, size, grid, errorImage, move;
    int rays = 1024;
    double errorScalePercent = 10;
};

struct SolverRun {
    const char* label;
    std::vector<std::string> flags;
};

struct RunOutcome {
    double solveMs = 0;
    std::uint64_t peakBytes = 0;
    Image fluence, display;
};

// Runs `luxel render` for one solver in a child process and collects what it wrote.
Result<RunOutcome> runSolver(const CompareSolversArgs& args, const SolverRun& solver,
                             const std::filesystem::path& dir) {
    const std::string exr = (dir / (std::string(solver.label) + ".exr")).string();
    const std::string png = (dir / (std::string(solver.label) + ".png")).string();
    const std::string log = (dir / (std::string(solver.label) + ".log")).string();
    std::vector<std::string> argv = {"/proc/self/exe", "render", args.scene, "--quiet", "--stats",
                                     "--out",          exr,      "--png",    png};
    if (!args.size.empty()) argv.insert(argv.end(), {"--size", args.size});
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

int runCompareSolvers(const CompareSolversArgs& args) {
    if (access(args.scene.c_str(), R_OK) != 0) {
        return reportError(Error("cannot open scene '" + args.scene + "'"));
    }
    if (auto size = parseSize(args.size); !size) return reportError(size.error());
    auto file = loadScene(args.scene, "");
    if (!file) return reportError(file.error());
    if (file->kind() != scene::SceneKind::TwoD) {
        return reportError(Error(args.scene + ": " + sceneKindPhrase(file->kind()) +
                                 "; compare-solvers compares the 2D "
                                 "solvers"));
    }
    if (!args.move.empty()) {
        return runCompareMovingLight(
            {args.scene, args.size, args.move, args.errorImage, args.rays, args.errorScalePercent});
    }
    // The CPU paths, so peak memory is the solver's own (no Vulkan driver loaded); RC marches the
    // pixel medium as the reference does.
    std::vector<SolverRun> solvers = {
        {"reference", {"--solver", "reference", "--rays", std::to_string(args.rays)}},
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
             {"--solver", "reference", "--rays", std::to_string(args.rays), "--seed", "2"}});
    }
    std::error_code ec;
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("luxel-compare-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir, ec);
    if (ec) return reportError(Error("cannot create " + dir.string() + ": " + ec.message()));

    std::vector<RunOutcome> runs;
    for (const SolverRun& solver : solvers) {
        auto run = runSolver(args, solver, dir);
        if (!run) {
            std::filesystem::remove_all(dir, ec);
            return reportError(run.error());
        }
        runs.push_back(std::move(*run));
    }
    std::filesystem::remove_all(dir, ec);

    const Image& reference = runs[0].fluence;
    std::printf("%s at %dx%d (reference: %d rays/pixel)\n", args.scene.c_str(), reference.width(),
                reference.height(), args.rays);
    std::printf("%-16s %10s %10s %10s %9s %12s\n", "solver", "ms", "rel. L1", "RMSE", "RMSE/mean",
                "peak memory");
    for (std::size_t i = 0; i < runs.size(); ++i) {
        auto e = compareImages(runs[i].fluence, reference);
        if (!e) return reportError(e.error());
        std::printf("%-16s %10.1f %10.4f %10.5f %8.2f%% %12s\n", solvers[i].label, runs[i].solveMs,
                    e->relativeL1, e->rmse,
                    e->meanReference > 0 ? 100.0 * e->rmse / e->meanReference : 0.0,
                    formatBytes(runs[i].peakBytes).c_str());
    }
    if (!args.grid.empty()) {
        std::vector<Image> displays;
        for (const RunOutcome& r : runs) displays.push_back(r.display);
        if (Status s = writePng(args.grid, sideBySide(displays)); !s) {
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
        if (Status s = writePng(args.errorImage, sideBySide(panels)); !s) {
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
    app.add_option("--grid", args->grid, "write the display images side by side (.png)");
    app.add_option("--error-image", args->errorImage,
                   "write the reference and each solver's signed error side by side (.png)");
    app.add_option("--error-scale", args->errorScalePercent,
                   "error image: the error (% of the mean fluence) drawn fully red or blue")
        ->check(CLI::Range(0.001, 1000.0))
        ->capture_default_str();
    app.add_option("--move", args->move,
                   "move the brightest light by DX,DY px and compare each solver's change");
    return [args] { return runCompareSolvers(*args); };
}

}  // namespace luxel::cli
