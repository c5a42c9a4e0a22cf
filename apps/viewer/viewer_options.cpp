// luxel-view command line (CLI11), turned into ViewerOptions.
#include "viewer_options.h"

#include <CLI/CLI.hpp>

#include "common/number_options.h"
#include "luxel/core/image_size.h"

namespace luxel::viewer {

Result<std::pair<int, int>> parseWindowSize(const std::string& text, const std::string& option) {
    auto size = parseImageSize(text, option);
    if (!size) return size.error();
    return std::pair{size->width, size->height};
}

Result<ParsedOptions> parseViewerOptions(const std::vector<std::string>& args) {
    ParsedOptions parsed;
    ViewerOptions& o = parsed.options;
    std::string size, internalSize, backend = "auto", solver = "hrc", merge = "bilinear-fix";
    CLI::App app{"luxel-view: interactive 2D radiance cascades, voxel and octree viewer",
                 "luxel-view"};
    app.add_option("scene", o.scene,
                   "2D scene (.json), voxel scene (\"type\": \"voxel\") or octree scene (\"type\": "
                   "\"octree\")")
        ->required();
    app.add_option("--size", size, "window size WxH");
    app.add_option("--internal-size", internalSize, "render size WxH (independent of the window)");
    app.add_option("--internal-scale", o.internalScale,
                   "render size as a fraction of the canvas (2D) or window (voxel, octree)")
        ->check(options::finiteIn(0.05, 4.0));
    app.add_option("--backend", backend, "auto | cpu | gpu");
    app.add_option("--device", o.device, "Vulkan device index or name part");
    app.add_option("--solver", solver,
                   "2D solver: hrc | rc | reference; voxel solver: raycast | ao | path");
    app.add_option("--merge", merge, "2D RC merge: vanilla | bilinear-fix");
    app.add_option("--exposure", o.exposure, "exposure in stops")
        ->check(options::finiteIn(-64.0, 64.0));
    app.add_option("--script", o.script, "timed input events (docs/viewer.md)");
    app.add_option("--record", o.recordFrames, "write the next N rendered frames as PNG")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--record-dir", o.recordDir, "folder for --record frames");
    app.add_option("--save", o.savePath,
                   "where Ctrl+S saves: the painted 2D scene, the voxel world (.vox)");
    app.add_option("--target-fps", o.targetFps,
                   "without --internal-size/--internal-scale, the internal size adapts to keep "
                   "this frame rate (0: fixed)")
        ->check(options::finiteIn(0.0, 1000.0));
    app.add_option("--frame", o.voxFrame,
                   "MagicaVoxel worlds: the animation frame to show (default: the scene's "
                   "\"frame\", else 0)")
        ->check(CLI::Range(0, 1 << 30));
    app.add_option("--spp", o.path.samplesPerPixel,
                   "voxel, path tracer: samples per pixel where the accumulation stops")
        ->check(CLI::Range(1, voxel::kMaxPathSamples));
    app.add_option("--max-bounces", o.path.maxBounces,
                   "voxel, path tracer: most reflections of the light reaching the eye")
        ->check(CLI::Range(0, voxel::kMaxPathBounces));
    app.add_option("--ao-rays", o.ao.rays, "voxel, sky visibility: rays per surface point")
        ->check(CLI::Range(1, voxel::kMaxSkyRays));
    app.add_option("--ao-radius", o.ao.radius,
                   "voxel, sky visibility: ray length in voxels (inf: whole sky visibility)");
    std::uint64_t seed = 1;
    app.add_option("--seed", seed, "voxel, path tracer and sky visibility: random seed");
    app.add_option("--threads", o.threads, "solver threads (0: all)")->check(CLI::Range(0, 1024));
    app.add_flag("--no-overlay", o.hideOverlay, "start with the panels hidden (F1 shows them)");

    std::vector<std::string> reversed(args.rbegin(), args.rend());
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        parsed.helpRequested = true;
        parsed.helpText = app.help();
        return parsed;
    } catch (const CLI::ParseError& e) {
        return Error(e.what());
    }
    // The names the CLI accepts, parsed by the same functions (luxel/gi2d/solver_choice.h,
    // luxel/gpu/backend_policy.h).
    auto parsedBackend = gpu::parseBackend(backend);
    if (!parsedBackend) return parsedBackend.error();
    // --solver names a 2D or a voxel solver; main() checks it against the scene's kind.
    // "rc" names a solver of both kinds: 2D radiance cascades or the voxel ones.
    if (solver == "rc") {
        o.voxelSolver = VoxelSolver::Cascades;
        o.solver2DGiven = app.count("--solver") > 0;
    } else if (auto voxelSolver = parseVoxelSolver(solver); voxelSolver) {
        o.voxelSolver = *voxelSolver;
        solver = "hrc";
    } else {
        o.solver2DGiven = app.count("--solver") > 0;
    }
    auto parsedSolver = gi2d::parseSolver2D(solver);
    if (!parsedSolver) {
        return Error(parsedSolver.error().message() + " (voxel scenes: raycast, ao, path, rc)");
    }
    auto parsedMerge = gi2d::parseRcMerge(merge);
    if (!parsedMerge) return parsedMerge.error();
    o.backend = *parsedBackend;
    o.solver = *parsedSolver;
    o.merge = *parsedMerge;
    if (!(o.ao.radius > 0.0)) {
        return Error("--ao-radius must be > 0 voxels (inf: whole sky visibility)");
    }
    o.path.seed = o.ao.seed = seed;
    for (const char* name : {"--spp", "--max-bounces", "--ao-rays", "--ao-radius", "--seed"}) {
        if (app.count(name) > 0) o.voxelFlagsGiven.push_back(name);
    }
    if (!size.empty()) {
        auto s = parseWindowSize(size, "--size");
        if (!s) return s.error();
        o.windowWidth = s->first;
        o.windowHeight = s->second;
    }
    if (!internalSize.empty()) {
        auto s = parseWindowSize(internalSize, "--internal-size");
        if (!s) return s.error();
        o.internalWidth = s->first;
        o.internalHeight = s->second;
    }
    return parsed;
}

}  // namespace luxel::viewer
