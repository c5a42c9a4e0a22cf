// `luxel compare-solvers` on a voxel scene: the path tracer is the reference (--spp samples);
// sky visibility (ambient occlusion) and the ray caster with physical lighting are measured
// against it: time, relative L1, RMSE, low-frequency RMSE (8 x 8 pixel block means, the error a
// smooth GI method is judged by: docs/algorithms/voxel-sky-visibility.md), the light each adds
// where the reference is dark (leaks through thin walls: docs/voxel-gi-measures.md) and peak
// memory. --sun-sweep measures flicker instead (compare_sun_sweep.cpp). --reference reuses a
// path-traced render (a converged one takes minutes) instead of rendering it again.
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/compare_solvers_run.h"
#include "commands/render_outputs.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/metrics.h"
#include "luxel/post/gi_measures.h"

namespace luxel::cli {

std::vector<SolverRun> voxelSolvers(int spp, int samples, int adaptiveSamples) {
    std::vector<SolverRun> runs{
        {"path",
         {"--solver", "path", "--spp", std::to_string(spp), "--backend", "cpu"},
         "path tracer"},
        {"ao", {"--solver", "ao", "--backend", "cpu"}, "sky visibility"},
        {"rc", {"--solver", "rc", "--backend", "cpu"}, "radiance cascades"},
        {"ray-caster", {"--lighting", "physical", "--backend", "cpu"}, "ray caster"},
    };
    if (samples > 0) {
        for (std::size_t i = 1; i < runs.size(); ++i) {
            runs[i].flags.insert(runs[i].flags.end(), {"--samples", std::to_string(samples)});
        }
    }
    if (adaptiveSamples >= 0) {
        runs[2].flags.insert(runs[2].flags.end(),
                             {"--adaptive-samples", std::to_string(adaptiveSamples)});
    }
    return runs;
}

namespace {

// --reference: a radiance EXR that `luxel render VOXEL.json --solver path` wrote for this scene
// at this size, checked by its size and, where its metadata has them, its solver and scene hash;
// `spp` becomes its samples per pixel.
Result<RunOutcome> reuseVoxelReference(const VoxelCompareRequest& request, int& spp) {
    const std::string& path = request.reference;
    if (!hasExtension(path, ".exr")) {
        return Error("--reference '" + path +
                     "' must be a radiance EXR (luxel render VOXEL.json --solver path --out "
                     "FILE.exr)");
    }
    ImageMetadata metadata;
    auto radiance = readExr(path, &metadata);
    if (!radiance) return radiance.error();
    auto file = loadScene(request.scene, request.size);
    if (!file) return file.error();
    const voxel::Camera& camera = file->voxel().camera;
    if (radiance->width() != camera.width() || radiance->height() != camera.height()) {
        return Error("--reference '" + path + "' is " + std::to_string(radiance->width()) + "x" +
                     std::to_string(radiance->height()) + " but " + request.scene + " renders at " +
                     std::to_string(camera.width()) + "x" + std::to_string(camera.height()) +
                     (request.size.empty() ? "" : " (--size)"));
    }
    if (const std::string* solver = findMetadata(metadata, "luxel.solver");
        solver != nullptr && *solver != "path") {
        return Error("--reference '" + path + "' was rendered by the " + *solver +
                     " solver, not the path tracer");
    }
    if (const std::string* hash = findMetadata(metadata, "luxel.scene.fnv1a64")) {
        auto bytes = readFileBytes(request.scene, "scene");
        if (!bytes) return bytes.error();
        if (*hash != fnv1a64Hex(*bytes)) {
            return Error("--reference '" + path + "' was rendered from another version of " +
                         request.scene + " (scene FNV-1a " + *hash + ", the file's now " +
                         fnv1a64Hex(*bytes) + ")");
        }
    }
    if (const std::string* samples = findMetadata(metadata, "luxel.samples")) {
        spp = std::atoi(samples->c_str());
    }
    RunOutcome out;
    if (const std::string* seconds = findMetadata(metadata, "luxel.render.seconds")) {
        out.solveMs = std::atof(seconds->c_str()) * 1e3;
    }
    out.fluence = std::move(*radiance);
    return out;
}

}  // namespace

int compareVoxelSolvers(const VoxelCompareRequest& request) {
    if (request.sunSweep > 0) return compareVoxelSunSweep(request);
    int spp = request.spp;
    std::optional<RunOutcome> reused;
    if (!request.reference.empty()) {
        auto outcome = reuseVoxelReference(request, spp);
        if (!outcome) return reportError(outcome.error());
        reused = std::move(*outcome);
    }
    const std::vector<SolverRun> solvers =
        voxelSolvers(spp, request.samples, request.adaptiveSamples);
    // A reused reference stands in for the first run.
    auto solved =
        runSolverProcesses(request.scene, request.size, std::span(solvers).subspan(reused ? 1 : 0));
    if (!solved) return reportError(solved.error());
    std::vector<RunOutcome> runs = std::move(*solved);
    if (reused) runs.insert(runs.begin(), std::move(*reused));

    const Image& reference = runs[0].fluence;
    const Image referenceBlocks = post::blockMeans(reference);
    std::printf("%s at %dx%d (reference: path tracer, %d samples/pixel%s%s)\n",
                request.scene.c_str(), reference.width(), reference.height(), spp,
                reused ? ", from " : "", request.reference.c_str());
    if (request.samples > 0) {
        std::printf("the other solvers: %d samples/pixel (--samples)\n", request.samples);
    }
    if (request.adaptiveSamples >= 0) {
        std::printf("radiance cascades: %d adaptive samples/pixel (--adaptive-samples)\n",
                    request.adaptiveSamples);
    }
    std::vector<post::DarkLeak> leaks;
    for (const RunOutcome& run : runs) {
        auto leak = post::darkRegionLeak(run.fluence, reference);
        if (!leak) return reportError(leak.error());
        leaks.push_back(*leak);
    }
    std::printf("dark region: %zu of %zu blocks of %dx%d px below %g%% of the reference mean\n",
                leaks[0].darkBlocks, leaks[0].blocks, post::kLowFrequencyBlock,
                post::kLowFrequencyBlock, 100.0 * post::kDarkFraction);
    std::printf("%-12s %10s %10s %10s %9s %13s %10s %12s\n", "solver", "ms", "rel. L1", "RMSE",
                "RMSE/mean", "low-freq/mean", "leak/mean", "peak memory");
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        auto e = compareImages(runs[i].fluence, reference);
        if (!e) return reportError(e.error());
        auto low = compareImages(post::blockMeans(runs[i].fluence), referenceBlocks);
        if (!low) return reportError(low.error());
        const double mean = e->meanReference > 0 ? e->meanReference : 1.0;
        std::printf("%-12s %10.1f %10.4f %10.5f %8.2f%% %12.2f%% %9.2f%% %12s\n", solvers[i].label,
                    runs[i].solveMs, e->relativeL1, e->rmse, 100.0 * e->rmse / mean,
                    100.0 * low->rmse / mean, 100.0 * leaks[i].leak,
                    formatBytes(runs[i].peakBytes).c_str());
        char error[96];
        std::snprintf(error, sizeof error, ", rel. L1 %.4f, leak %.2f%%", e->relativeL1,
                      100.0 * leaks[i].leak);
        labels.push_back(std::string(solvers[i].label) + "\n" + formatDuration(runs[i].solveMs) +
                         (i == 0 ? ", " + std::to_string(spp) + " spp" : error));
    }
    if (!request.grid.empty()) {
        std::vector<Image> displays;
        ImageMetadata metadata =
            renderMetadata(request.scene, "compare-solvers", reference.width(), reference.height());
        setNumber(metadata, "luxel.dark_fraction", post::kDarkFraction);
        setNumber(metadata, "luxel.dark_blocks", static_cast<double>(leaks[0].darkBlocks));
        std::string order;
        for (std::size_t i = 0; i < runs.size(); ++i) {
            displays.push_back(runs[i].display);
            setMetadata(metadata, "luxel.panel" + std::to_string(i + 1) + "." + solvers[i].label,
                        labels[i].substr(labels[i].find('\n') + 1));
            setNumber(metadata, std::string("luxel.leak.") + solvers[i].label, leaks[i].leak);
            order += (i == 0 ? "" : ", ") + std::string(solvers[i].title);
        }
        setMetadata(metadata, "luxel.content", "display, tonemapped; panels left to right");
        if (Status s = writeLabelledGrid(request.grid, std::move(displays), labels, metadata); !s) {
            return reportError(s.error());
        }
        std::printf("wrote %s (left to right: %s)\n", request.grid.c_str(), order.c_str());
    }
    return 0;
}

}  // namespace luxel::cli
