// `luxel render`: scene -> fluence image (EXR linear or PNG tonemapped) and display PNG.
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "luxel/core/image_io.h"
#include "luxel/core/parallel.h"
#include "luxel/core/progress.h"
#include "luxel/core/timer.h"
#include "luxel/core/tonemap.h"
#include "luxel/gi2d/display.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::cli {
namespace {

struct RenderArgs {
    std::string scene, solver = "reference", size, out, png, tonemap = "aces";
    int rays = gi2d::ReferenceOptions{}.rays;
    int threads = 0;
    int supersample = 16;
    std::uint64_t seed = 1;
    float exposure = 0.0f;
    bool quiet = false;
};

bool hasExtension(const std::string& path, const std::string& ext) {
    if (path.size() < ext.size()) return false;
    std::string tail = path.substr(path.size() - ext.size());
    for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return tail == ext;
}

int runRender(const RenderArgs& args) {
    if (args.solver != "reference") {
        return reportError(Error("unknown solver '" + args.solver + "' (available: reference)"));
    }
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

    Stopwatch rasterTime;
    auto medium = loadMedium(args.scene, args.size, args.supersample);
    if (!medium) return reportError(medium.error());
    const double rasterSeconds = rasterTime.seconds();
    const int w = medium->width(), h = medium->height();

    ProgressBar progress("render", static_cast<std::uint64_t>(h), !args.quiet);
    gi2d::ReferenceOptions options;
    options.rays = args.rays;
    options.seed = args.seed;
    options.onRowsDone = [&](int rows) { progress.advance(static_cast<std::uint64_t>(rows)); };
    Stopwatch solveTime;
    auto fluence = gi2d::solveReference(*medium, options);
    progress.finish();
    if (!fluence) return reportError(fluence.error());
    const double solveSeconds = solveTime.seconds();

    const Image out = hasExtension(args.out, ".png") ? toneMap(*fluence, tone) : *fluence;
    if (Status s = writeImage(args.out, out); !s) return reportError(s.error());
    if (!args.png.empty()) {
        if (!hasExtension(args.png, ".png")) {
            return reportError(Error("--png '" + args.png + "' must end in .png"));
        }
        if (Status s = writePng(args.png, gi2d::displayImage(*medium, *fluence, tone)); !s) {
            return reportError(s.error());
        }
    }
    if (!args.quiet) {
        const double rays = static_cast<double>(gi2d::referenceRayCount(w, h, args.rays));
        std::printf("%s: %dx%d, solver %s, %d rays/pixel, %d threads\n", args.scene.c_str(), w, h,
                    args.solver.c_str(), args.rays,
                    args.threads > 0 ? args.threads : hardwareThreads());
        std::printf("  raster %.3f s, solve %.3f s (%.2f Mrays/s)\n", rasterSeconds, solveSeconds,
                    rays / solveSeconds * 1e-6);
        std::printf("  wrote %s%s%s\n", args.out.c_str(), args.png.empty() ? "" : ", ",
                    args.png.c_str());
    }
    return 0;
}

}  // namespace

Runner addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    app.add_option("scene", args->scene, "scene file (.json)")->required();
    app.add_option("--solver", args->solver, "light transport solver")->capture_default_str();
    app.add_option("--size", args->size, "render size WIDTHxHEIGHT (default: the scene canvas)");
    app.add_option("--rays", args->rays, "directions per pixel (reference solver)")
        ->capture_default_str();
    app.add_option("--threads", args->threads, "worker threads (0 = all cores)")
        ->capture_default_str();
    app.add_option("--seed", args->seed, "random seed")->capture_default_str();
    app.add_option("--supersample", args->supersample, "edge samples per pixel side")
        ->capture_default_str();
    app.add_option("--out", args->out, "fluence image: .exr (linear float) or .png (tonemapped)")
        ->required();
    app.add_option("--png", args->png, "also write the display image (emission + fluence)");
    app.add_option("--exposure", args->exposure, "exposure in stops for PNG output")
        ->capture_default_str();
    app.add_option("--tonemap", args->tonemap, "tone curve for PNG output: clamp, reinhard, aces")
        ->capture_default_str();
    app.add_flag("--quiet,-q", args->quiet, "no progress bar or summary");
    return [args] { return runRender(*args); };
}

}  // namespace luxel::cli
