// What `luxel compare-solvers` shares between its 2D and voxel comparisons: each solver runs as
// `luxel render` in a child process, so its peak memory is its own.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/core/image_metadata.h"

namespace luxel::cli {

struct SolverRun {
    const char* label;
    std::vector<std::string> flags;  // `luxel render` flags that choose and set up the solver
    const char* title = "";          // what the solver is, in words (grid captions)
};

struct RunOutcome {
    double solveMs = 0;
    std::uint64_t peakBytes = 0;  // 0: not measured (a reused reference)
    Image fluence, display;       // the linear image (fluence or radiance) and the display PNG
};

// Runs `luxel render SCENE [--size SIZE] FLAGS` in a child process, in `dir`, and collects what
// it wrote, its solve time (--stats) and its peak resident memory.
Result<RunOutcome> runSolverProcess(const std::string& scene, const std::string& size,
                                    const SolverRun& solver, const std::filesystem::path& dir);

// runSolverProcess for each solver in turn, in a temporary folder removed afterwards; the first
// failure stops the runs and is returned.
Result<std::vector<RunOutcome>> runSolverProcesses(const std::string& scene,
                                                   const std::string& size,
                                                   std::span<const SolverRun> solvers);

// "812 ms" or "59.2 s".
std::string formatDuration(double ms);

// The panels side by side, each captioned with its label (one text size for all, so every
// caption fits), as an sRGB PNG with `metadata`: the grids of compare-solvers.
Status writeLabelledGrid(const std::string& path, std::vector<Image> panels,
                         const std::vector<std::string>& labels, const ImageMetadata& metadata);

// `luxel compare-solvers` on a voxel scene: the path tracer (the reference), sky visibility,
// radiance cascades and the ray caster with physical lighting: time, error, low-frequency error,
// light leaked into the reference's dark places, peak memory; with sunSweep, each solver's flicker
// as the sun turns (docs/voxel-gi-measures.md).
struct VoxelCompareRequest {
    std::string scene, size, grid;
    int spp = 256;       // the path-traced reference's samples per pixel
    int sunSweep = 0;    // frames of the sun sweep (0: none, else >= 2)
    double sunStep = 1;  // degrees the sun turns about the vertical between frames
    // A path-traced radiance EXR of this scene at this size to use as the reference instead of
    // rendering one (`luxel render VOXEL.json --solver path --out FILE.exr`); "" renders it.
    std::string reference;
    // Samples per pixel of the solvers other than the path tracer (--samples; 0: the scene's).
    int samples = 0;
    // The radiance cascades' adaptive samples (--adaptive-samples; -1: the scene's, 0: off).
    int adaptiveSamples = -1;
};
int compareVoxelSolvers(const VoxelCompareRequest& request);

// The voxel solvers compare-solvers runs, the reference (the path tracer) first; a new solver is
// one more entry.
// `samples` > 0 passes --samples to the others, `adaptiveSamples` >= 0 --adaptive-samples to the
// radiance cascades.
std::vector<SolverRun> voxelSolvers(int spp, int samples = 0, int adaptiveSamples = -1);

// `compareVoxelSolvers` with request.sunSweep frames (compare_sun_sweep.cpp).
int compareVoxelSunSweep(const VoxelCompareRequest& request);

}  // namespace luxel::cli
