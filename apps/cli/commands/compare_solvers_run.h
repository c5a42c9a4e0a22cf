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

namespace luxel::cli {

struct SolverRun {
    const char* label;
    std::vector<std::string> flags;  // `luxel render` flags that choose and set up the solver
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

// `luxel compare-solvers` on a voxel scene: the path tracer (the reference), sky visibility and
// the ray caster with physical lighting: time, error, low-frequency error, peak memory.
struct VoxelCompareRequest {
    std::string scene, size, grid;
    int spp = 256;  // the path-traced reference's samples per pixel
};
int compareVoxelSolvers(const VoxelCompareRequest& request);

}  // namespace luxel::cli
