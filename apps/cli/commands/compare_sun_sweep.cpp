// `luxel compare-solvers VOXEL.json --sun-sweep N [--sun-step DEG]`: every voxel solver at N sun
// directions, each turned DEG further about the vertical axis, and per solver the flicker of its
// low-frequency image that the reference's change does not have (docs/voxel-gi-measures.md). The
// reference keeps its seed in every frame, so its noise changes only as much as the sun makes it;
// the reference with another seed shows what flicker that noise leaves.
#include <cstdio>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/compare_solvers_run.h"
#include "commands/render_outputs.h"
#include "luxel/core/metrics.h"
#include "luxel/post/gi_measures.h"

namespace luxel::cli {

int compareVoxelSunSweep(const VoxelCompareRequest& request) {
    std::vector<SolverRun> solvers =
        voxelSolvers(request.spp, request.samples, request.adaptiveSamples);
    // The reference again with other random numbers: its flicker is the reference's noise alone,
    // the floor under every other solver's.
    SolverRun seed2 = solvers[0];
    seed2.label = "path-seed2";
    seed2.title = "path tracer with seed 2";
    seed2.flags.insert(seed2.flags.end(), {"--seed", "2"});
    solvers.push_back(seed2);
    // frames[s][k]: solver s under the sun of frame k.
    std::vector<std::vector<Image>> frames(solvers.size());
    std::vector<double> ms(solvers.size(), 0.0), relativeL1(solvers.size(), 0.0);
    std::vector<Image> firstDisplays;
    for (int k = 0; k < request.sunSweep; ++k) {
        char yaw[32];
        std::snprintf(yaw, sizeof yaw, "%.9g", k * request.sunStep);
        std::vector<SolverRun> turned = solvers;
        for (SolverRun& solver : turned)
            solver.flags.insert(solver.flags.end(), {"--sun-yaw", yaw});
        auto solved = runSolverProcesses(request.scene, request.size, turned);
        if (!solved) return reportError(solved.error());
        for (std::size_t s = 0; s < solvers.size(); ++s) {
            RunOutcome& run = (*solved)[s];
            // The reference (s = 0) is already in frames[0] when the others are compared.
            auto e = compareImages(run.fluence, s == 0 ? run.fluence : frames[0].back());
            if (!e) return reportError(e.error());
            ms[s] += run.solveMs / request.sunSweep;
            relativeL1[s] += e->relativeL1 / request.sunSweep;
            if (k == 0) firstDisplays.push_back(std::move(run.display));
            frames[s].push_back(std::move(run.fluence));
        }
    }
    const Image& first = frames[0][0];
    std::vector<post::SunFlicker> flicker;
    for (const std::vector<Image>& solverFrames : frames) {
        auto f = post::sunFlicker(solverFrames, frames[0]);
        if (!f) return reportError(f.error());
        flicker.push_back(*f);
    }
    std::printf(
        "%s at %dx%d, %d sun directions %g degrees apart about the vertical (reference: path "
        "tracer, %d samples/pixel, random seed 1 in every frame)\n",
        request.scene.c_str(), first.width(), first.height(), request.sunSweep, request.sunStep,
        request.spp);
    std::printf("the reference's low-frequency change between frames: %.3f%% of its mean\n",
                100.0 * flicker[0].referenceChange);
    std::printf(
        "path-seed2: random seed 2 instead of 1; its flicker is the reference's noise alone\n");
    std::printf("%-12s %10s %10s %13s\n", "solver", "ms/frame", "rel. L1", "flicker/mean");
    for (std::size_t s = 0; s < solvers.size(); ++s) {
        std::printf("%-12s %10.1f %10.4f %12.3f%%\n", solvers[s].label, ms[s], relativeL1[s],
                    100.0 * flicker[s].flicker);
    }
    if (!request.grid.empty()) {
        // The first frame of each solver, captioned with its flicker over the whole sweep.
        std::vector<std::string> labels;
        for (std::size_t s = 0; s < solvers.size(); ++s) {
            char text[96];
            std::snprintf(text, sizeof text, "%s\nflicker %.3f%%", solvers[s].label,
                          100.0 * flicker[s].flicker);
            labels.push_back(text);
        }
        ImageMetadata metadata =
            renderMetadata(request.scene, "compare-solvers", first.width(), first.height());
        setNumber(metadata, "luxel.sun_sweep.frames", request.sunSweep);
        setNumber(metadata, "luxel.sun_sweep.step_degrees", request.sunStep);
        setNumber(metadata, "luxel.sun_sweep.reference_change", flicker[0].referenceChange);
        std::string order;
        for (std::size_t s = 0; s < solvers.size(); ++s) {
            setNumber(metadata, std::string("luxel.flicker.") + solvers[s].label,
                      flicker[s].flicker);
            order += (s == 0 ? "" : ", ") + std::string(solvers[s].title);
        }
        setMetadata(metadata, "luxel.content",
                    "display, tonemapped, the sweep's first frame; panels left to right");
        if (Status st = writeLabelledGrid(request.grid, std::move(firstDisplays), labels, metadata);
            !st) {
            return reportError(st.error());
        }
        std::printf("wrote %s (the first frame, left to right: %s)\n", request.grid.c_str(),
                    order.c_str());
    }
    return 0;
}

}  // namespace luxel::cli
